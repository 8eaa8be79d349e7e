#include "systems/street_system.hpp"

#include <algorithm>

#include "systems/param_uniforms.hpp"
#include "systems/scene_select.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc street_desc() {
    return {.label = "street", .fragment = "street.frag"};
}
}  // namespace

Result<void> prepare_street(gpu::Device& device, StreetRenderer& street) {
    return street.pass.ensure(device, street_desc);
}

void street_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   StreetRenderer& street, const RenderTarget& target) {
    if (selected_scene(params) != Scene::Street) return;
    if (!street.pass.ensure_or_log(device, street_desc)) return;
    const gpu::FrameTarget& frame = target.target;
    auto pass = device.begin_pass({.label = "street", .target = frame, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(street.pass.pipeline);
    set_param_uniforms(pass, params);
    pass.set("u_time", shader_time(clock.sim_time))
        .set("u_aspect", static_cast<float>(frame.size.x) / static_cast<float>(std::max(frame.size.y, 1)))
        .set("u_seed", params.i(ParamId::rain_seed));
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
