#include "bench/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "systems/water/wave_system.hpp"

namespace puddle::bench {

double rms_slope(const std::vector<float>& heights, int resolution) {
    if (resolution < 2 || heights.size() < static_cast<std::size_t>(resolution) * resolution * 2) return 0;
    const auto n = static_cast<std::size_t>(resolution);
    auto h = [&](std::size_t x, std::size_t z) { return static_cast<double>(heights[2 * (z * n + x)]); };
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t z = 0; z < n; ++z)
        for (std::size_t x = 0; x + 1 < n; ++x, ++count) sum += std::pow(h(x + 1, z) - h(x, z), 2);
    for (std::size_t z = 0; z + 1 < n; ++z)
        for (std::size_t x = 0; x < n; ++x, ++count) sum += std::pow(h(x, z + 1) - h(x, z), 2);
    return std::sqrt(sum / static_cast<double>(count));
}

Warmup warm_to_steady_state(app::Engine& engine) {
    auto slope = [&] {
        const auto& field = engine.world().resource<systems::WaveField>();
        return rms_slope(field.read_heights(engine.device()), field.resolution);
    };
    Warmup w;
    w.calm_slope = slope();
    double high = w.calm_slope;
    int flat_seconds = 0;
    while (w.steps < steady_max_steps && flat_seconds < steady_seconds) {
        for (int k = 0; k < steady_check_steps; ++k) engine.run_stage(ecs::Stage::Simulate);
        w.steps += steady_check_steps;
        const double s = slope();
        flat_seconds = s > high * (1 + steady_growth) ? 0 : flat_seconds + 1;
        high = std::max(high, s);
        w.steady_slope = s;
    }
    w.steady = flat_seconds >= steady_seconds;
    return w;
}

}  // namespace puddle::bench
