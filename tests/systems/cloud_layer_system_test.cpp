// The procedural sky's clouds drift (systems/sky/cloud_layer_system.hpp): where they are is a function of
// the clock's time, so months lose no precision and every screen of a wall agrees; in the picture the clouds
// move and the city under them does not.
#include "systems/sky/cloud_layer_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

using params::ParamId;

TEST(CloudDrift, TheOffsetIsTheClocksTimeTimesTheSpeedWrappedToATile) {
    params::Params params = make_params({"environment.cloud_drift=0.4"});
    systems::FrameClock clock;
    systems::Clouds clouds;
    const long double tiles_per_second =
        static_cast<long double>(0.4f) / 60.0L / static_cast<long double>(assets::cloud_tile_units);
    for (double t : {0.0, 1.0, 3600.0, 86400.0 * 365.0 * 3.0}) {  // up to three years
        clock.sim_time = t;
        systems::cloud_drift_system(params, clock, clouds);
        const long double along = static_cast<long double>(t) * tiles_per_second;
        const auto wrapped = [](long double v) { return static_cast<double>(v - std::floor(v)); };
        EXPECT_NEAR(clouds.offset.x, wrapped(along * 0.8L), 1e-6) << "at " << t << " s";
        EXPECT_NEAR(clouds.offset.y, wrapped(along * 0.6L), 1e-6) << "at " << t << " s";
        EXPECT_GE(clouds.offset.x, 0.0f);
        EXPECT_LT(clouds.offset.x, 1.0f);
    }
    params.set(ParamId::environment_cloud_drift, 0.0f, params::ParamSource::CommandLine);
    clock.sim_time = 1e6;
    systems::cloud_drift_system(params, clock, clouds);
    EXPECT_EQ(clouds.offset, glm::vec2(0.0f)) << "no drift: the clouds stay where they began";
}

// Looking up from the street, the rain stopped: the sky over the rooftops fills the top of the frame,
// buildings its bottom.
assets::Image sky_after(double seconds, float drift) {
    auto engine = make_engine(
        make_params({"camera.position=[0,2,0]", "camera.target=[-3,12,1]", "camera.fov=90", "rain.rate=0",
                     "overlay.rain=false", "environment.cloud_drift=" + std::to_string(drift)}),
        {480, 270});
    if (!engine) return {};
    engine->world().resource<systems::FrameClock>().epoch_time = seconds;  // the clock's time from here
    return render_frames(*engine, 1);
}

TEST(CloudDrift, TheCloudsMoveAndTheCityUnderThemDoesNot) {
    const assets::Image start = sky_after(0.0, 6.0);
    const assets::Image later = sky_after(20.0, 6.0);  // two deck heights on
    const assets::Image still_start = sky_after(0.0, 0.0);
    const assets::Image still_later = sky_after(20.0, 0.0);
    ASSERT_FALSE(start.empty());
    const auto crop = [](const assets::Image& img, int x0, int x1, int y0, int y1) {
        assets::Image out = assets::Image::make(x1 - x0, y1 - y0);
        for (int y = y0; y < y1; ++y) std::copy_n(img.pixel8(x0, y), 4 * (x1 - x0), out.pixel8(0, y - y0));
        return out;
    };
    const auto rows = [&](const assets::Image& img, int y0, int y1) {
        return crop(img, 0, img.width, y0, y1);
    };
    // The sky (the top third) changes as the clouds pass; without drift it is the same picture.
    EXPECT_GT(compare_images(rows(start, 0, 90), rows(later, 0, 90), 1).fraction_over, 0.1);
    EXPECT_EQ(compare_images(rows(still_start, 0, 90), rows(still_later, 0, 90), 0).fraction_over, 0.0);
    // The city stands still: inside every lit window and sign (bright, with bright neighbours, in the first
    // picture) of the left half nothing changes (the right half has the moon, which the clouds cross), but
    // for the slits of sky between two towers that the filtered picture blends into a window beside them.
    const auto bright = [&](int x, int y) {
        const std::uint8_t* p = start.pixel8(x, y);
        return std::max({p[0], p[1], p[2]}) >= 200;
    };
    int lit = 0, moved = 0;
    for (int y = 1; y + 1 < start.height; ++y)
        for (int x = 1; x < start.width / 2; ++x) {
            if (!(bright(x, y) && bright(x - 1, y) && bright(x + 1, y) && bright(x, y - 1) &&
                  bright(x, y + 1)))
                continue;
            ++lit;
            const std::uint8_t* a = start.pixel8(x, y);
            const std::uint8_t* b = later.pixel8(x, y);
            moved +=
                std::abs(a[0] - b[0]) > 2 || std::abs(a[1] - b[1]) > 2 || std::abs(a[2] - b[2]) > 2 ? 1 : 0;
        }
    EXPECT_GT(lit, 1000) << "the view has lit windows";
    EXPECT_LT(moved, lit / 30) << "lit windows changed";
}

}  // namespace
}  // namespace puddle::test
