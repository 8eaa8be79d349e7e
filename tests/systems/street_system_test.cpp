// The rainy street at night (systems/street/street_system.hpp, REFERENCE.md section 3): the wet ground
// mirrors the street about the horizon where street.horizon puts it, ripples brighten the puddles, the
// lamps and windows light it, and it drifts toward the viewer without a jump.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

// street.horizon is the horizon's height above the bottom of the screen: the street's vanishing line,
// above it the facades and the sky, below it the wet ground. Tinted green (street.water_tint), the ground
// shows where it starts down the middle of the picture: at the line, a few rows lower where the haze is
// thick. Fails if the horizon ignored the parameter or were measured from the top.
TEST(StreetScene, TheGroundStartsAtTheHorizon) {
    for (const float horizon : {0.35f, 0.6f}) {
        SCOPED_TRACE(horizon);
        const auto img = render_with(
            {"scene.kind=street", "street.horizon=" + std::to_string(horizon), "street.water_tint=0,1,0",
             "street.wet_reflection=1", "street.lamps=0", "street.lightning=0", "overlay.rain=false"},
            2, {320, 180});
        ASSERT_EQ(img.height, 180);
        const double line = img.height * (1.0 - horizon);  // rows from the top to the horizon
        auto green = [&](int y) {  // mean green excess over the middle tenth of the row
            double sum = 0;
            for (int x = img.width * 9 / 20; x < img.width * 11 / 20; ++x) {
                const std::uint8_t* p = img.pixel8(x, y);
                sum += p[1] - 0.5 * (p[0] + p[2]);
            }
            return sum / (img.width / 10);
        };
        int first = 0;
        while (first < img.height && green(first) < 30) ++first;
        EXPECT_GE(first, line - 1);
        EXPECT_LE(first, line + 8);
        EXPECT_GT(green(img.height - 1), 60) << "the near ground is tinted";
    }
}

TEST(StreetScene, RipplesBrightenThePuddles) {
    const auto none = render_with({"scene.kind=street", "street.ripples=0", "street.splashes=0"}, 40);
    const auto many = render_with({"scene.kind=street", "street.ripples=32", "street.splashes=0"}, 40);
    // Only below the horizon (rows from 58% of the height down).
    EXPECT_GT(mean_luma(many, 0, 53, 160, 90), mean_luma(none, 0, 53, 160, 90) + 0.2);
    EXPECT_GT(compare_images(none, many, 8).fraction_over, 0.002);
}

// Pixels in rows [y0, y1) whose red is at least `level` and above their blue: warm light.
int warm_pixels(const assets::Image& img, int y0, int y1, int level) {
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel8(x, y);
            if (p[0] >= level && p[0] > p[2] + 20) ++n;
        }
    return n;
}

// The lamps light the street: their heads and glow above the horizon, their reflections in the wet
// ground below it; with street.lamps = 0 neither.
TEST(StreetScene, TheLampsAndTheirReflectionsLightTheStreet) {
    const auto lit =
        render_with({"scene.kind=street", "street.lit_windows=0", "overlay.rain=false"}, 2, {320, 180});
    const auto dark = render_with(
        {"scene.kind=street", "street.lit_windows=0", "street.lamps=0", "overlay.rain=false"}, 2, {320, 180});
    const int horizon = static_cast<int>(180 * (1.0 - 0.42));  // street.horizon's default, rows from the top
    EXPECT_GT(warm_pixels(lit, 0, horizon, 120), 20 + 2 * warm_pixels(dark, 0, horizon, 120));
    EXPECT_GT(warm_pixels(lit, horizon + 4, 180, 80), 20 + 2 * warm_pixels(dark, horizon + 4, 180, 80))
        << "their reflections";
}

// street.lit_windows: more of the facades' windows lit, more light above the horizon.
TEST(StreetScene, MoreLitWindowsBrightenTheFacades) {
    const auto few =
        render_with({"scene.kind=street", "street.lit_windows=0.05", "street.lamps=0"}, 2, {320, 180});
    const auto many =
        render_with({"scene.kind=street", "street.lit_windows=0.8", "street.lamps=0"}, 2, {320, 180});
    const int horizon = static_cast<int>(180 * (1.0 - 0.42));
    EXPECT_GT(mean_luma(many, 0, 0, 320, horizon), mean_luma(few, 0, 0, 320, horizon) + 5);
}

// The street drifts toward the viewer (street.ground_drift): two seconds at half a unit a second later the
// facades and lamps have moved a building on; with the drift off they stand still (only the sky's clouds
// and lightning, off here, would move).
TEST(StreetScene, TheStreetDriftsTowardTheViewer) {
    const std::initializer_list<std::string> still = {"scene.kind=street",  "street.cloud_drift=0",
                                                      "street.lightning=0", "street.ripples=0",
                                                      "street.splashes=0",  "overlay.rain=false"};
    auto at = [&](int frames, const std::string& drift) {
        std::vector<std::string> sets(still);
        sets.push_back("street.ground_drift=" + drift);
        params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
        apply_sets(p, sets);
        auto engine = make_engine(p, {320, 180});
        return engine ? render_frames(*engine, frames) : assets::Image{};
    };
    EXPECT_GT(compare_images(at(2, "0.5"), at(122, "0.5"), 16).fraction_over, 0.05);
    EXPECT_EQ(compare_images(at(2, "0"), at(122, "0"), 0).max_channel_diff, 0);
}

}  // namespace
}  // namespace puddle::test
