// A display that runs for years never jumps: the looks that are functions of time
// (ocean, street, rain overlay, grid drops) render frames on both sides of every period the old code
// wrapped time at, and after 10^8 s of uptime, and those frames must differ about as much as two frames
// the same time apart early in the run. Shaders used to get time as float(fmod(seconds, 4096)): each
// look jumped every 68 minutes, and an unwrapped float time stands still at 10^8 s (its step is 8 s).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

// The frame whose last simulation step is at `seconds`: the clock's epoch is moved so that the next
// step lands there exactly, as it would after that long a run.
assets::Image frame_at(app::Engine& engine, double seconds) {
    auto& clock = engine.world().resource<systems::FrameClock>();
    clock.epoch_time = seconds - clock.step_seconds;
    clock.epoch_step = clock.step_index;
    return render_frames(engine, 1);
}

// Mean channel difference (0..255) between the frames at t - dt and t + dt.
double change_across(app::Engine& engine, double t, double dt) {
    return compare_images(frame_at(engine, t - dt), frame_at(engine, t + dt), 8).mean_abs_diff;
}

constexpr double frame = 1.0 / 60.0;
constexpr double control_time = 100.0;
// Frames straddling a period may differ by this many times the control's difference, no more: a
// different part of the picture moves by a different amount, a jump changes everything at once.
constexpr double margin = 2.0;

struct Look {
    const char* name;
    std::vector<std::string> sets;
    double dt = frame;  // the frames compared are 2 dt apart
};

const Look ocean{"ocean", {"scene.kind=ocean"}};
const Look street{"street", {"scene.kind=street"}};
// The window's runs over a glass without still beads: only the running drops and the cars move.
const Look window{"window", {"scene.kind=window", "window.beads=0", "window.streams=32", "rain.rate=20"}};
// The rain overlay over a street that stands still (its clouds, ground, lightning, ripples and splashes
// off), so only the streaks move. A streak
// falls a quarter of its cell in two frames, about as far as a jump moves it, so frames a tenth of a
// frame apart tell a jump from a fall. The grid's thin rings likewise (at a jump every drop moves).
const Look rain{"rain overlay",
                {"scene.kind=street", "street.cloud_drift=0", "street.ground_drift=0", "street.lightning=0",
                 "street.ripples=0", "street.splashes=0", "overlay.rain=true"},
                frame / 10};
const Look grid{
    "grid drops", {"drops.model=grid", "grid.cycle=0.1", "grid.drops_per_second=2000"}, frame / 10};

std::unique_ptr<app::Engine> engine_for(const Look& look) {
    params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
    apply_sets(p, look.sets);
    return make_engine(p, render_test_size);
}

// Frames straddling `t` change no more than frames straddling the control time.
void expect_continuous_at(const Look& look, double t, double control_at = control_time) {
    auto engine = engine_for(look);
    ASSERT_TRUE(engine);
    const double control = change_across(*engine, control_at, look.dt);
    const double across = change_across(*engine, t, look.dt);
    std::printf("%s: frames %.4f s apart differ by %.3f at %.1f s (control), %.3f across %.1f s\n", look.name,
                2 * look.dt, control, control_at, across, t);
    EXPECT_GT(control, 0.0) << look.name
                            << ": the control frames must move for the comparison to mean anything";
    EXPECT_LE(across, margin * control) << look.name << ": the picture jumps at " << t << " s";
}

// After a very long run the picture still moves, and moves as much as early on: neither frozen (a float
// time whose step has grown past a frame) nor noise (a phase that lost its precision).
void expect_moving_normally_at(const Look& look, double t) {
    auto engine = engine_for(look);
    ASSERT_TRUE(engine);
    const double control = change_across(*engine, control_time, look.dt);
    const double late = change_across(*engine, t, look.dt);
    std::printf("%s: frames %.4f s apart differ by %.3f at %.0f s (control), %.3f at %.0f s\n", look.name,
                2 * look.dt, control, control_time, late, t);
    EXPECT_GE(late, control / margin) << look.name << ": frozen at " << t << " s";
    EXPECT_LE(late, margin * control) << look.name << ": jumps or shimmers at " << t << " s";
}

// The old shaders wrapped time every 4096 s.
constexpr double old_wrap = 4096.0;
// 10^8 s (3.2 years) of uptime, moved to the old wrap just below it (24414 * 4096 s), where the old
// shaders also jumped.
constexpr double long_uptime = 24414.0 * old_wrap;

TEST(TimeContinuity, OceanDoesNotJumpAtTheOldWrap) {
    expect_continuous_at(ocean, old_wrap);
}
TEST(TimeContinuity, StreetDoesNotJumpAtTheOldWrap) {
    expect_continuous_at(street, old_wrap);
}
TEST(TimeContinuity, WindowDoesNotJumpAtTheOldWrap) {
    expect_continuous_at(window, old_wrap);
}
TEST(TimeContinuity, RainOverlayDoesNotJumpAtTheOldWrap) {
    expect_continuous_at(rain, old_wrap);
}

TEST(TimeContinuity, OceanMovesNormallyAfterTenToTheEightSeconds) {
    expect_moving_normally_at(ocean, long_uptime);
}
TEST(TimeContinuity, StreetMovesNormallyAfterTenToTheEightSeconds) {
    expect_moving_normally_at(street, long_uptime);
}
TEST(TimeContinuity, WindowMovesNormallyAfterTenToTheEightSeconds) {
    expect_moving_normally_at(window, long_uptime);
}
TEST(TimeContinuity, RainOverlayMovesNormallyAfterTenToTheEightSeconds) {
    expect_moving_normally_at(rain, long_uptime);
}

// The grid drops count cycles in an int the CPU wrapped at 2^31: with grid.cycle = 0.1 s that came after
// 6.8 years, and every cell moved its drop mid-ring. Rings live a tenth of a second, so the control is a
// whole number of cycles earlier: every ring at the same age, only the drops' places differ.
TEST(TimeContinuity, GridDropsDoNotJumpAfterTwoToTheThirtyOneCycles) {
    const auto cycle =
        static_cast<double>(make_params({"grid.cycle=0.1"}).get<params::ParamId::grid_cycle>());
    expect_continuous_at(grid, 2147483648.0 * cycle, (2147483648.0 - 1000.0) * cycle);
}

}  // namespace
}  // namespace puddle::test
