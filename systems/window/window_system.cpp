#include "systems/window/window_system.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "render/shader_hash.hpp"
#include "render/shader_phase.hpp"
#include "systems/water/rain_rate.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc window_desc() {
    return {.label = "window", .vertex = "view_window.vert", .fragment = "window.frag"};
}

constexpr std::uint32_t stream_salt = 307u;
}  // namespace

double window_stream_period(const params::Params& params, int column) {
    const double run =
        (static_cast<double>(params.get<ParamId::window_view_height>()) + 2.0 * window_run_margin) /
        static_cast<double>(params.get<ParamId::window_slide_speed>());
    const auto seed = static_cast<std::uint32_t>(params.get<ParamId::rain_seed>());
    const double u = render::shader_unit_float(
        render::shader_hash3(static_cast<std::uint32_t>(column), stream_salt, seed));
    return run * (1.8 + 1.4 * u) + 1.2 * window_trail_refill;
}

double window_wetness(double rate_mm_h) {
    return 1.0 - std::exp(-std::max(rate_mm_h, 0.0) / 2.5);
}

WindowTime window_time(const params::Params& params, double seconds) {
    WindowTime wt;
    const render::Repetition life =
        render::repetition_at(seconds, params.get<ParamId::window_bead_life>(), 0.0);
    wt.bead_phase = static_cast<float>(life.age / params.get<ParamId::window_bead_life>());
    if (wt.bead_phase >= 1.0f) wt.bead_phase = 0.0f;  // a float age rounded up to the whole life
    wt.bead_cycle = static_cast<int>(life.index);
    const render::LatticeShift cars = render::lattice_shift(seconds, window_traffic_cells_per_second);
    wt.traffic_shift = cars.fraction;
    wt.traffic_cells = cars.cells;
    const double rate = params.get<ParamId::rain_rate>(), drift = params.get<ParamId::rain_drift>();
    wt.wetness = static_cast<float>(window_wetness(rain_rate_at(rate, drift, seconds)));
    const auto seed = static_cast<std::uint32_t>(params.get<ParamId::rain_seed>());
    const int streams = params.get<ParamId::window_streams>();
    for (int i = 0; i < streams && i < window_max_streams; ++i) {
        const auto column = static_cast<std::uint32_t>(i);
        const double offset = render::shader_unit_float(render::shader_hash3(column, stream_salt + 1u, seed));
        const render::Repetition r = render::repetition_at(seconds, window_stream_period(params, i), offset);
        // Whether this run goes is decided by the rain when it set off, so a shower's change of rate
        // never makes a drop vanish halfway down.
        const double wet_then =
            window_wetness(rain_rate_at(rate, drift, seconds - static_cast<double>(r.age)));
        const double go =
            render::shader_unit_float(render::shader_hash3(column, r.index, seed ^ (stream_salt + 2u)));
        const bool runs = go < std::sqrt(wet_then);  // none on a dry window, about a third in drizzle
        wt.stream_age[static_cast<std::size_t>(i)] = runs ? r.age : static_cast<float>(window_resting_age);
        wt.stream_repeat[static_cast<std::size_t>(i)] = static_cast<int>(r.index ^ seed);
    }
    return wt;
}

WindowRenderer::WindowRenderer() : pass(window_desc()) {}

void window_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   WindowRenderer& window, const RenderTarget& target) {
    window.pass.draw(device, params, target, gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
        const WindowTime wt = window_time(params, clock.sim_time);
        pass.set("u_aspect", target.view.view_aspect(target.target.size))
            .set("u_bead_phase", wt.bead_phase)
            .set("u_bead_cycle", wt.bead_cycle)
            .set("u_traffic_shift", wt.traffic_shift)
            .set("u_traffic_cells", wt.traffic_cells)
            .set("u_wetness", wt.wetness)
            .set("u_stream_age", std::span<const float>(wt.stream_age))
            .set("u_stream_repeat", std::span<const int>(wt.stream_repeat));
    });
}

void add_window_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& window = world.insert_resource<WindowRenderer>();
    LookEntry entry = fullscreen_look(Scene::window, window.pass);
    entry.takes_rain_overlay = false;  // the rain beyond the glass is out of focus: no sharp streaks
    world.resource<Looks>().entries.push_back(std::move(entry));
    schedule.add(ecs::Stage::Render, "window", window_system)
        .run_if(look_is(Scene::window))
        .run_if(output_on());
}

}  // namespace puddle::systems
