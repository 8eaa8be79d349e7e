// Rain on a window (systems/window/window_system.hpp, scene.kind = window): the still beads follow the
// rain, window.blur grows the city's lights into larger discs, and a running drop moves down the glass
// leaving a trail behind it.
#include "systems/window/window_system.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"
#include "systems/clock/frame_clock.hpp"

namespace puddle::test {
namespace {

constexpr glm::ivec2 size{320, 180};

params::Params window_params(const std::vector<std::string>& sets) {
    params::Params p = make_params({"scene.kind=window", "rain.seed=11", "rain.drift=0"});
    apply_sets(p, sets);
    return p;
}

// The frame whose last simulation step is at `seconds` (the clock's epoch moved there).
assets::Image window_at(const std::vector<std::string>& sets, double seconds) {
    auto engine = make_engine(window_params(sets), size);
    if (!engine) return {};
    auto& clock = engine->world().resource<systems::FrameClock>();
    clock.epoch_time = seconds - clock.step_seconds;
    clock.epoch_step = clock.step_index;
    return render_frames(*engine, 1);
}

// Pixels (counted) whose luma passes `level`.
int pixels_over(const assets::Image& img, double level) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) n += mean_luma(img, x, y, x + 1, y + 1) > level ? 1 : 0;
    return n;
}

TEST(WindowScene, TheStillBeadsFollowTheRain) {
    const std::vector<std::string> still{"window.streams=0", "window.traffic=0"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.end(), still.begin(), still.end());
        return window_at(more, 30.0);
    };
    const auto dry = with({"window.beads=0"});
    const auto drizzle = with({"rain.rate=0.3"}), downpour = with({"rain.rate=20"});
    ASSERT_FALSE(dry.empty() || drizzle.empty() || downpour.empty());
    const double light = compare_images(drizzle, dry, 6).fraction_over,
                 heavy = compare_images(downpour, dry, 6).fraction_over;
    std::printf("glass covered by beads: %.3f in drizzle, %.3f in a downpour\n", light, heavy);
    EXPECT_GT(light, 0.002) << "a few beads in drizzle";
    EXPECT_GT(heavy, 0.05) << "beads all over the glass in a downpour";
    EXPECT_GT(heavy, 3.0 * light);
}

// rain.seed chooses where the beads sit; the city behind the glass stays the same.
TEST(WindowScene, TheSeedChoosesWhereTheBeadsSit) {
    const std::vector<std::string> still{"window.streams=0", "window.traffic=0"};
    auto with = [&](const std::string& seed, const std::string& beads) {
        std::vector<std::string> sets = still;
        sets.push_back("rain.seed=" + seed);
        sets.push_back("window.beads=" + beads);
        return window_at(sets, 30.0);
    };
    EXPECT_GT(compare_images(with("3", "0.6"), with("12345", "0.6"), 6).fraction_over, 0.02);
    EXPECT_EQ(compare_images(with("3", "0"), with("12345", "0"), 0).max_channel_diff, 0) << "the same city";
}

TEST(WindowScene, BlurGrowsTheLightsIntoDiscs) {
    const std::vector<std::string> clear{"window.beads=0", "window.streams=0", "window.traffic=0"};
    auto with = [&](const std::string& blur) {
        std::vector<std::string> sets = clear;
        sets.push_back("window.blur=" + blur);
        return window_at(sets, 10.0);
    };
    const int sharp = pixels_over(with("0"), 90.0), soft = pixels_over(with("1"), 90.0);
    std::printf("bright pixels: %d at window.blur = 0, %d at 1\n", sharp, soft);
    EXPECT_GT(sharp, 0) << "the city has lights";
    EXPECT_GT(soft, 2 * sharp) << "out of focus, each light is a larger disc";
}

// The glass is in focus and the rain beyond it is not: the window takes no sharp streaks (Looks'
// takes_rain_overlay), whatever overlay.rain says; the street still does.
TEST(WindowScene, TakesNoRainStreaks) {
    const auto with = window_at({"overlay.rain=true", "overlay.rain_opacity=1"}, 20.0);
    const auto without = window_at({"overlay.rain=false"}, 20.0);
    ASSERT_FALSE(with.empty() || without.empty());
    EXPECT_EQ(compare_images(with, without, 0).max_channel_diff, 0);
    auto street = [](const std::string& rain) {
        params::Params p =
            make_params({"scene.kind=street", "overlay.rain_opacity=1", "overlay.rain=" + rain});
        auto engine = make_engine(p, size);
        return engine ? render_frames(*engine, 20) : assets::Image{};
    };
    EXPECT_GT(compare_images(street("true"), street("false"), 0).max_channel_diff, 0)
        << "the street takes them";
}

// The bottom row (from the top) where `img` differs from `dry` by more than `threshold`, or -1.
int lowest_changed_row(const assets::Image& img, const assets::Image& dry, int threshold) {
    for (int y = img.height - 1; y >= 0; --y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(img.pixel8(x, y)[c]) - int(dry.pixel8(x, y)[c])) > threshold) return y;
    return -1;
}

TEST(WindowScene, ARunningDropMovesDownAndLeavesATrail) {
    // One column, big drops (6 cm of glass), slow, and rain heavy enough that the run goes.
    const std::vector<std::string> sets{"window.streams=1",        "window.beads=0",
                                        "window.traffic=0",        "rain.rate=50",
                                        "window.view_height=0.06", "window.slide_speed=0.02"};
    const params::Params p = window_params(sets);
    double t1 = -1.0;
    for (double t = 0.0; t < 600.0 && t1 < 0.0; t += 0.05) {
        const float age = systems::window_time(p, t).stream_age[0];
        if (age > 0.6f && age < 0.65f) t1 = t;
    }
    ASSERT_GE(t1, 0.0) << "no run of column 0 in 10 minutes";
    const double t2 = t1 + 0.5;
    std::vector<std::string> none = sets;
    none.push_back("window.streams=0");
    const auto a = window_at(sets, t1), b = window_at(sets, t2), dry_a = window_at(none, t1),
               dry_b = window_at(none, t2);
    ASSERT_FALSE(a.empty() || b.empty() || dry_a.empty() || dry_b.empty());
    const int bottom_a = lowest_changed_row(a, dry_a, 20), bottom_b = lowest_changed_row(b, dry_b, 20);
    std::printf("the drop's lowest row: %d at %.2f s, %d at %.2f s\n", bottom_a, t1, bottom_b, t2);
    ASSERT_GE(bottom_a, 0) << "a drop on the glass";
    EXPECT_GT(bottom_b, bottom_a + 3) << "half a second later it is lower";
    // Above the drop, the trail: the wet edges and the tiny beads it leaves differ from the dry glass.
    const auto trail = compare_images(b, dry_b, 2);
    EXPECT_GT(trail.fraction_over, compare_images(a, dry_a, 2).fraction_over) << "the trail grows as it runs";
}

}  // namespace
}  // namespace puddle::test
