#include "systems/rain_overlay_system.hpp"

#include "render/param_uniforms.hpp"
#include "render/shader_phase.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc rain_desc() {
    return {.label = "rain streaks",
            .vertex = "view_window.vert",
            .fragment = "rain_streaks.frag",
            .blend = gpu::Blend::Lit};
}
}  // namespace

glm::vec4 rain_layer_falls(double seconds, double speed) {
    glm::vec4 falls{};
    for (int i = 0; i < 4; ++i)
        falls[i] =
            render::periodic_phase(seconds, speed * rain_layer_speeds[static_cast<std::size_t>(i)], 1.0);
    return falls;
}

Result<void> prepare_rain_overlay(gpu::Device& device, RainOverlay& rain) {
    return rain.pass.ensure(device, {}, rain_desc);
}

void rain_overlay_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                         RainOverlay& rain, const RenderTarget& target) {
    const render::BuiltPipeline* built = rain.pass.request(device, {}, rain_desc);
    if (!built) return;  // switched on live: drawn once built
    const gpu::FrameTarget& frame = target.target;
    auto pass = device.begin_pass({.label = "rain streaks", .target = frame, .load = gpu::LoadOp::Load});
    pass.set_pipeline(built->pipeline);
    render::set_param_uniforms(pass, built->params, params);
    pass.set("u_layer_fall", rain_layer_falls(clock.sim_time, params.get<ParamId::overlay_rain_speed>()))
        .set("u_view_window", target.view.uniform())
        .set("u_resolution", target.view.view_size(frame.size))
        .set("u_seed", params.get<ParamId::rain_seed>());
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
