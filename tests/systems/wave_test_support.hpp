#pragma once
// Helpers for wave-field tests: drive the wave system directly with chosen drops and measure the field.

#include <cmath>
#include <vector>

#include "app/engine.hpp"
#include "systems/water/drop_system.hpp"
#include "systems/water/wave_system.hpp"

namespace puddle::test {

struct Field {
    int n = 0;
    std::vector<float> hv;  // (current, previous) per texel, rows by z
    double cur(int x, int y) const { return hv[2 * (std::size_t(y) * n + x)]; }
    double prev(int x, int y) const { return hv[2 * (std::size_t(y) * n + x) + 1]; }
};

inline Field read_field(app::Engine& e) {
    e.make_current();  // tests keep two engines; the one that rendered last has its context current
    auto& field = e.world().resource<systems::WaveField>();
    return {field.resolution, field.read_heights(e.device())};
}

// One wave step with the given drops (x, y in texels, amount).
inline void step(app::Engine& e, std::initializer_list<glm::vec3> drops = {}) {
    systems::LiveDrops live;
    for (const glm::vec3& d : drops) live.drops[std::size_t(live.count++)] = glm::vec4(d, 0.0f);
    e.make_current();
    systems::wave_system(e.device(), e.params(), e.world().resource<systems::FrameClock>(), live,
                         e.world().resource<systems::WaveField>());
}

// The discrete energy the leapfrog scheme conserves at damping 1 (k = 1/2):
//   E = sum (u[n+1] - u[n])^2 + k * sum over edges (grad u[n+1] . grad u[n]).
inline double energy(const Field& f) {
    double kinetic = 0, potential = 0;
    for (int y = 0; y < f.n; ++y)
        for (int x = 0; x < f.n; ++x) {
            const double dt = double(f.cur(x, y)) - f.prev(x, y);
            kinetic += dt * dt;
            if (x + 1 < f.n)
                potential +=
                    (double(f.cur(x + 1, y)) - f.cur(x, y)) * (double(f.prev(x + 1, y)) - f.prev(x, y));
            if (y + 1 < f.n)
                potential +=
                    (double(f.cur(x, y + 1)) - f.cur(x, y)) * (double(f.prev(x, y + 1)) - f.prev(x, y));
        }
    return kinetic + 0.5 * potential;
}

// Radius (texels) at which the radially averaged |height| peaks, around centre c, along directions
// within the given angle range.
inline double peak_radius(const Field& f, double cx, double cy) {
    std::vector<double> sum(std::size_t(f.n), 0.0), count(std::size_t(f.n), 0.0);
    for (int y = 0; y < f.n; ++y)
        for (int x = 0; x < f.n; ++x) {
            const double r = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            const auto bin = std::size_t(std::lround(r));
            if (bin < sum.size()) sum[bin] += std::abs(f.cur(x, y)), count[bin] += 1;
        }
    std::size_t best = 0;
    for (std::size_t i = 1; i < sum.size(); ++i)
        if (count[i] > 0 && sum[i] / count[i] > sum[best] / std::max(count[best], 1.0)) best = i;
    return double(best);
}

}  // namespace puddle::test
