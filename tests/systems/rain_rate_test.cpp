// How hard it rains and how many drops that is (systems/water/rain_rate.hpp), and the capillary step's
// factors (systems/water/capillary_step.hpp).
#include "systems/water/rain_rate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "params/param_store.hpp"
#include "systems/water/capillary_step.hpp"

namespace puddle::systems {
namespace {

// Shared LOOK.md: moderate rain (5 mm/h) is hundreds of impacts a square metre a second, drizzle tens,
// a downpour many hundreds. Marshall-Palmer sizes from 1 mm give more, smaller drops than "all 2 mm".
TEST(RainRate, ImpactsFollowTheRateInHundredsASquareMetreASecond) {
    EXPECT_EQ(impacts_per_square_metre_second(0.0), 0.0);
    const double drizzle = impacts_per_square_metre_second(0.5);
    const double moderate = impacts_per_square_metre_second(5.0);
    const double downpour = impacts_per_square_metre_second(20.0);
    EXPECT_GT(drizzle, 20.0);
    EXPECT_LT(drizzle, 200.0);
    EXPECT_GT(moderate, 330.0) << "more than if every drop were 2 mm";
    EXPECT_LT(moderate, 1500.0);
    EXPECT_GT(downpour, moderate);
    // Heavier rain has bigger drops (lambda falls with the rate), so the count grows slower than the rate.
    EXPECT_LT(downpour / moderate, 4.0);
    EXPECT_LT(marshall_palmer_slope(20.0), marshall_palmer_slope(5.0));
    EXPECT_NEAR(marshall_palmer_slope(1.0), 4.1, 1e-9);
}

TEST(RainRate, DriftWandersBetweenLullsAndShowersAndNeverFreezes) {
    EXPECT_EQ(rain_rate_at(3.0, 0.0, 1234.5), 3.0);
    double lo = 1e9, hi = 0.0;
    int changes = 0;
    double last = rain_rate_at(3.0, 1.0, 0.0);
    for (int s = 0; s <= 3 * 3600; s += 10) {
        const double r = rain_rate_at(3.0, 1.0, s);
        lo = std::min(lo, r), hi = std::max(hi, r);
        if (std::abs(r - last) > 1e-6) ++changes;
        last = r;
    }
    EXPECT_GE(lo, 3.0 / 4.0 - 1e-9);
    EXPECT_LE(hi, 3.0 * std::exp2(1.32) + 1e-9);
    EXPECT_LT(lo, 3.0 / 2.0) << "a lull within three hours";
    EXPECT_GT(hi, 3.0 * 1.8) << "a shower within three hours";
    EXPECT_GT(changes, 1000) << "it changes all the time";
    // Slowly: within 10 s it changes by under 15%.
    for (int s = 0; s < 3600; s += 97)
        EXPECT_LT(std::abs(rain_rate_at(3.0, 1.0, s + 10) / rain_rate_at(3.0, 1.0, s) - 1.0), 0.15) << s;
    // Not the same picture an hour later: the rate at t and t + 1 h differ somewhere over the hour.
    double most = 0.0;
    for (int s = 0; s < 3600; s += 60)
        most = std::max(most, std::abs(rain_rate_at(3.0, 1.0, s + 3600) - rain_rate_at(3.0, 1.0, s)));
    EXPECT_GT(most, 0.5);
}

TEST(CapillaryStep, SubstepsKeepTheLeapfrogStableAtAnyResolution) {
    for (int res : {128, 512, 1024, 2048}) {
        params::Params params;
        ASSERT_TRUE(params.set<params::ParamId::wave_resolution>(res, params::ParamSource::CommandLine));
        const CapillaryStep s = capillary_step(params, 1.0 / 60.0);
        EXPECT_NEAR(s.dt * s.substeps, 1.0 / 60.0, 1e-12);
        // The checkerboard mode's growth factor stays within the unit circle: 8a + 64b < 4, 16 v / 2 < 1.
        EXPECT_LT(8.0 * s.a + 64.0 * s.b, 4.0 * 0.7 * 0.7 + 1e-6) << res;
        EXPECT_LE(8.0 * s.v, 0.7 + 1e-6) << res;
        if (s.substeps > 1) {  // one pass fewer would pass a limit: no more passes than needed
            const double k = double(s.substeps) / (s.substeps - 1);
            EXPECT_TRUE((8.0 * s.a + 64.0 * s.b) * k * k >= 1.96 - 1e-4 || 8.0 * s.v * k >= 0.7 - 1e-4)
                << res;
        }
        EXPECT_NEAR(s.texel_m, static_cast<double>(params.get<params::ParamId::wave_size>()) / res, 1e-9);
    }
}

}  // namespace
}  // namespace puddle::systems
