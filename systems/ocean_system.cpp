#include "systems/ocean_system.hpp"

#include <algorithm>

#include "systems/camera_basis.hpp"
#include "systems/param_uniforms.hpp"
#include "systems/scene_select.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc ocean_desc() {
    return {.label = "ocean", .fragment = "ocean.frag"};
}
}  // namespace

Result<void> prepare_ocean(gpu::Device& device, OceanRenderer& ocean) {
    return ocean.pass.ensure(device, ocean_desc);
}

void ocean_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                  OceanRenderer& ocean, const RenderTarget& target) {
    if (selected_scene(params) != Scene::Ocean) return;
    if (!ocean.pass.ensure_or_log(device, ocean_desc)) return;
    const gpu::FrameTarget& frame = target.target;
    const float aspect = static_cast<float>(frame.size.x) / static_cast<float>(std::max(frame.size.y, 1));
    const CameraBasis cam =
        camera_basis(params.v3(ParamId::ocean_camera_position), params.v3(ParamId::ocean_camera_target),
                     params.f(ParamId::camera_fov), aspect);
    auto pass = device.begin_pass({.label = "ocean", .target = frame, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(ocean.pass.pipeline);
    set_param_uniforms(pass, params);
    pass.set("u_time", shader_time(clock.sim_time))
        .set("u_cam_forward", cam.forward)
        .set("u_cam_right", cam.right)
        .set("u_cam_up", cam.up)
        .set("u_cam_scale", cam.scale);
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
