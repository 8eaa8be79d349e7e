// The rain overlay (systems/rain_overlay/rain_overlay_system.hpp): streak pixels grow with the density,
// vanish at zero opacity or density, and take the rain colour.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

// Pixels the overlay changed (by more than 8 of 255 in any channel) against the same frame without it.
double streak_fraction(std::initializer_list<std::string> overlay_sets) {
    const auto plain = render_with({"scene.kind=street", "overlay.rain=false"}, 10);
    std::vector<std::string> sets{"scene.kind=street", "overlay.rain=true"};
    sets.insert(sets.end(), overlay_sets);
    params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
    apply_sets(p, sets);
    auto engine = make_engine(p, render_test_size);
    if (!engine) return -1;
    return compare_images(plain, render_frames(*engine, 10), 8).fraction_over;
}

TEST(RainOverlay, MoreDensityGivesMoreStreakPixels) {
    const double sparse = streak_fraction({"overlay.rain_density=0.4"});
    const double dense = streak_fraction({"overlay.rain_density=2"});
    EXPECT_GT(sparse, 0.005);
    EXPECT_GT(dense, 1.5 * sparse) << dense << " vs " << sparse;
}

TEST(RainOverlay, OffOrTransparentChangesNothing) {
    EXPECT_EQ(streak_fraction({"overlay.rain_opacity=0"}), 0.0);
    EXPECT_EQ(streak_fraction({"overlay.rain_density=0"}), 0.0);
}

TEST(RainOverlay, StreaksTakeTheRainColour) {
    const auto plain = render_with({"scene.kind=street", "overlay.rain=false"}, 2);
    const auto red = render_with({"scene.kind=street", "overlay.rain=true", "overlay.rain_color=1,0,0",
                                  "overlay.rain_opacity=1", "overlay.rain_density=2"},
                                 2);
    int redder = 0, bluer = 0;
    for (std::size_t i = 0; i < red.data.size(); i += 4) {
        const int dr = red.data[i] - plain.data[i], db = red.data[i + 2] - plain.data[i + 2];
        if (dr > 8) ++redder;
        if (db > 8) ++bluer;
    }
    EXPECT_GT(redder, 50);
    EXPECT_EQ(bluer, 0);
}

}  // namespace
}  // namespace puddle::test
