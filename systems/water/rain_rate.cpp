#include "systems/water/rain_rate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace puddle::systems {

double marshall_palmer_slope(double rate_mm_h) {
    return 4.1 * std::pow(std::max(rate_mm_h, 0.01), -0.21);
}

double impacts_per_square_metre_second(double rate_mm_h) {
    if (!(rate_mm_h > 0.0)) return 0.0;
    const double lambda = marshall_palmer_slope(rate_mm_h);
    // E[D^3] of the truncated exponential, by the midpoint rule (64 intervals are exact to 1e-4).
    constexpr int n = 64;
    double weight = 0.0, cubes = 0.0;
    for (int i = 0; i < n; ++i) {
        const double d = min_drop_mm + (max_drop_mm - min_drop_mm) * (i + 0.5) / n;
        const double w = std::exp(-lambda * d);
        weight += w;
        cubes += w * d * d * d;
    }
    const double mean_volume_mm3 = std::numbers::pi / 6.0 * cubes / weight;
    return rate_mm_h * 1e6 / 3600.0 / mean_volume_mm3;
}

double rain_rate_at(double rate_mm_h, double drift, double time_s) {
    const double minutes = time_s / 60.0;
    const double two_pi = 2.0 * std::numbers::pi;
    // In -1..1; the phases keep the start of a run from always being the same point of the cycle.
    const double wander =
        (0.5 * std::sin(two_pi * minutes / 6.1 + 0.4) + 0.3 * std::sin(two_pi * minutes / 17.3 + 2.1) +
         0.2 * std::sin(two_pi * minutes / 41.9 + 4.0));
    // Lulls go down to a quarter, showers up to 2.5 times: more time near the rate than at the extremes.
    const double stops = wander < 0.0 ? 2.0 * wander : 1.32 * wander;
    return rate_mm_h * std::exp2(drift * stops);
}

}  // namespace puddle::systems
