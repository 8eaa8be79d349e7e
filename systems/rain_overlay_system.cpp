#include "systems/rain_overlay_system.hpp"

#include "systems/param_uniforms.hpp"
#include "systems/scene_select.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc rain_desc() {
    return {.label = "rain streaks", .fragment = "rain_streaks.frag", .blend = gpu::Blend::Alpha};
}
}  // namespace

Result<void> prepare_rain_overlay(gpu::Device& device, RainOverlay& rain) {
    return rain.pass.ensure(device, rain_desc);
}

void rain_overlay_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                         RainOverlay& rain, const RenderTarget& target) {
    if (!params.b(ParamId::overlay_rain)) return;
    if (!rain.pass.ensure_or_log(device, rain_desc)) return;
    const gpu::FrameTarget& frame = target.target;
    auto pass = device.begin_pass({.label = "rain streaks", .target = frame, .load = gpu::LoadOp::Load});
    pass.set_pipeline(rain.pass.pipeline);
    set_param_uniforms(pass, params);
    pass.set("u_time", shader_time(clock.sim_time))
        .set("u_resolution", glm::vec2(frame.size))
        .set("u_seed", params.i(ParamId::rain_seed));
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
