#include "systems/rain_overlay/rain_overlay_system.hpp"

#include <algorithm>

#include "render/shader_phase.hpp"
#include "systems/water/rain_rate.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc rain_desc() {
    return {.label = "rain streaks",
            .vertex = "rain_streaks.vert",
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

double streak_density_factor(const params::Params& params, double sim_time) {
    if (params.get<ParamId::wave_model>() != params::WaveModel::capillary) return 1.0;
    constexpr double usual_mm_h = 3.0;  // the default rain.rate, at which overlay.rain_density reads as set
    const double rate = rain_rate_at(static_cast<double>(params.get<ParamId::rain_rate>()),
                                     static_cast<double>(params.get<ParamId::rain_drift>()), sim_time);
    return std::clamp(rate / usual_mm_h, 0.0, 2.5);
}

RainOverlay::RainOverlay() : pass(rain_desc()) {}

void rain_overlay_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                         RainOverlay& rain, const RenderTarget& target) {
    rain.pass.draw_with(
        device, params, target, gpu::LoadOp::Load,
        [&](gpu::RenderPass& pass) {
            pass.set("u_layer_fall",
                     rain_layer_falls(clock.sim_time, params.get<ParamId::overlay_rain_speed>()))
                .set("u_resolution", target.view.view_size(target.target.size))
                .set("u_seed", params.get<ParamId::rain_seed>())
                .set("u_streak_strength", static_cast<float>(streak_density_factor(params, clock.sim_time)));
        },
        [](gpu::RenderPass& pass) { pass.draw_quads(rain_streak_quads()); });
}

Result<void> add_rain_overlay_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& rain = world.insert_resource<RainOverlay>();
    if (world.resource<params::Params>().get<ParamId::overlay_rain>())
        if (auto r = rain.pass.prepare(world.resource<gpu::Device>()); !r) return r;
    schedule.add(ecs::Stage::Render, "rain overlay", rain_overlay_system)
        .run_if(rain_overlay_on())
        .run_if(output_on());
    return {};
}

}  // namespace puddle::systems
