// The window's clock (systems/window/window_system.hpp): every run leaves the view and its trail refills
// before its column runs again, lighter rain rests more columns, and a run that set off goes on whatever
// the rain does meanwhile.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "support/gpu_fixture.hpp"
#include "systems/window/window_system.hpp"

namespace puddle::test {
namespace {

using params::ParamId;
using systems::window_max_streams;

TEST(WindowTime, EveryRunLeavesTheViewAndItsTrailRefillsBeforeTheColumnRunsAgain) {
    for (const auto& sets : {std::initializer_list<std::string>{},
                             {"window.view_height=0.05", "window.slide_speed=0.5"},
                             {"window.view_height=1", "window.slide_speed=0.005"}}) {
        const params::Params p = make_params(sets);
        const double height = p.get<ParamId::window_view_height>(),
                     speed = p.get<ParamId::window_slide_speed>();
        // The slowest drop runs at 0.6 times the average; it has left when it ran the view and the margin.
        const double slowest_run = (height + 2.0 * systems::window_run_margin) / (0.6 * speed);
        for (int i = 0; i < window_max_streams; ++i) {
            SCOPED_TRACE(i);
            EXPECT_GT(systems::window_stream_period(p, i), slowest_run + systems::window_trail_refill);
        }
    }
}

// Runs that go, over an hour of frames a second apart, at a steady rain rate.
int runs_in_an_hour(const std::string& rate) {
    const params::Params p = make_params({"rain.rate=" + rate, "rain.drift=0", "window.streams=32"});
    std::map<std::pair<int, int>, bool> runs;  // (column, repeat): goes
    for (double t = 0.0; t < 3600.0; t += 1.0) {
        const systems::WindowTime wt = systems::window_time(p, t);
        for (int i = 0; i < window_max_streams; ++i)
            runs[{i, wt.stream_repeat[static_cast<std::size_t>(i)]}] =
                wt.stream_age[static_cast<std::size_t>(i)] < systems::window_resting_age;
    }
    int going = 0;
    for (const auto& [run, goes] : runs) going += goes ? 1 : 0;
    return going;
}

TEST(WindowTime, LighterRainRunsFewerDrops) {
    const int drizzle = runs_in_an_hour("0.3"), downpour = runs_in_an_hour("20");
    std::printf("runs in an hour: %d in drizzle (0.3 mm/h), %d in a downpour (20 mm/h)\n", drizzle, downpour);
    EXPECT_GT(drizzle, 0) << "some drops run in drizzle too";
    EXPECT_EQ(runs_in_an_hour("0"), 0) << "none on a dry window";
    EXPECT_GT(downpour, 2 * drizzle);
    EXPECT_GT(systems::window_wetness(20.0), 0.99);
    EXPECT_LT(systems::window_wetness(0.3), 0.15);
}

// rain.drift = 1 swings the rate between a quarter and two and a half times rain.rate over minutes: a run
// that set off keeps going (or resting) until its column's next run.
TEST(WindowTime, ARunThatSetOffGoesOnWhileTheRainChanges) {
    const params::Params p = make_params({"rain.rate=1", "rain.drift=1", "window.streams=32"});
    std::map<std::pair<int, int>, bool> decided;
    int changes_seen = 0;
    float lowest = 1.0f, highest = 0.0f;
    for (double t = 0.0; t < 7200.0; t += 0.25) {
        const systems::WindowTime wt = systems::window_time(p, t);
        lowest = std::min(lowest, wt.wetness);
        highest = std::max(highest, wt.wetness);
        for (int i = 0; i < window_max_streams; ++i) {
            const auto at = static_cast<std::size_t>(i);
            const bool goes = wt.stream_age[at] < systems::window_resting_age;
            const auto [it, fresh] = decided.try_emplace({i, wt.stream_repeat[at]}, goes);
            if (!fresh) {
                ASSERT_EQ(it->second, goes) << "column " << i << " changed its mind at " << t << " s";
                ++changes_seen;
            }
        }
    }
    EXPECT_GT(highest - lowest, 0.3f) << "the rain did change: wetness from " << lowest << " to " << highest;
    EXPECT_GT(changes_seen, 0);
}

// The beads' life and the cars' drift stay exact after years: the phase within [0, 1), the count of
// lives whole.
TEST(WindowTime, TheBeadsLifeIsExactAfterYears) {
    const params::Params p = make_params({"window.bead_life=45"});
    const double t = 1.0e8 + 0.5 * 45.0;  // half a life past a whole number of lives (10^8 / 45 is not whole)
    const systems::WindowTime a = systems::window_time(p, t), b = systems::window_time(p, t + 4.5);
    EXPECT_GE(a.bead_phase, 0.0f);
    EXPECT_LT(a.bead_phase, 1.0f);
    const double advanced = (b.bead_cycle - a.bead_cycle) + (b.bead_phase - a.bead_phase);
    EXPECT_NEAR(advanced, 0.1, 1e-4) << "4.5 s is a tenth of a life, at 10^8 s as at the start";
}

}  // namespace
}  // namespace puddle::test
