// Tests for systems/clock/wall_steps.hpp: the frame clock driven by an injected wall clock. A screen joins by
// a bounded warm-up, then simulates the step its vblank falls in; clock steps (an NTP correction) either
// way are re-synced or caught up within a bounded number of frames, never by thousands of steps in one.
#include "systems/clock/wall_steps.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/log_lines.hpp"

namespace puddle::systems {
namespace {

using params::ParamId;
using params::ParamSource;

constexpr std::int64_t start_ns = 1'764'590'400LL * ns_per_second + 3'000'000;  // 2025-12-01 12:00:00.003
constexpr std::int64_t frame_ns = 16'666'667;                                   // 60 Hz

// One screen: the wall steps system and the simulate stage's step counter, on a clock the test sets.
struct Screen {
    Screen() {
        params.set<ParamId::wall_clock>(params::WallClockMode::realtime, ParamSource::CommandLine);
        wall.now_ns = [this] { return now; };
    }
    // One frame at the current time; returns the steps it simulated.
    int frame() {
        wall_steps_system(wall, power, look, params, steps, clock);
        const int due = clock.steps_due;
        for (int i = 0; i < due; ++i) begin_step_system(clock);
        most_in_a_frame = std::max(most_in_a_frame, due);
        return due;
    }
    // The step this frame's vblank falls in.
    std::int64_t target() const {
        const auto latency = std::llround(static_cast<double>(params.get<ParamId::wall_latency>()) * 1e9);
        return step_at(now + latency, params.get<ParamId::wave_steps_per_second>());
    }
    bool in_step() const { return static_cast<std::int64_t>(clock.step_index) == target(); }
    // Frames at 60 Hz until in step; returns how many (a limit fails the test).
    int frames_until_in_step(int limit = 100) {
        for (int n = 1; n <= limit; ++n) {
            now += frame_ns;
            frame();
            if (in_step()) return n;
        }
        ADD_FAILURE() << "not in step after " << limit << " frames";
        return limit;
    }

    std::int64_t now = start_ns;
    params::Params params;
    WallClock wall;
    OutputPower power;
    ShownLook look;
    WallSteps steps;
    FrameClock clock;
    int most_in_a_frame = 0;
};

std::int64_t warmup_steps(const Screen& s) {
    return std::llround(static_cast<double>(s.params.get<ParamId::wall_warmup>()) *
                        s.params.get<ParamId::wave_steps_per_second>());
}

TEST(WallSteps, JoiningWarmsUpOverBoundedFramesThenFollowsTheClock) {
    Screen s;
    s.frame();
    EXPECT_EQ(s.clock.field_generation, 1u);  // the field starts flat
    EXPECT_EQ(s.steps.resyncs, 1u);
    const int catch_up = s.params.get<ParamId::wall_catch_up_steps>();
    // 1200 steps (20 s) at 60 a frame while the clock moves a step a frame: 59 steps gained a frame.
    const int frames = 1 + s.frames_until_in_step();
    EXPECT_LE(frames, (warmup_steps(s) + catch_up - 2) / (catch_up - 1) + 1);
    EXPECT_GE(frames, warmup_steps(s) / catch_up);
    EXPECT_EQ(s.most_in_a_frame, catch_up);
    // In step: a step a frame, the one the vblank falls in, and sim_time is that step's wall time.
    for (int i = 0; i < 600; ++i) {
        s.now += frame_ns;
        s.frame();
        ASSERT_TRUE(s.in_step()) << "frame " << i;
    }
    EXPECT_EQ(s.clock.field_generation, 1u);
    EXPECT_DOUBLE_EQ(s.clock.sim_time, static_cast<double>(s.target()) / 60.0);
}

// Two screens whose frames start at different moments of the 60 Hz period, started 3.7 s apart, simulate
// the same steps once both are in step: the step is the clock's, not the screen's.
TEST(WallSteps, ScreensStartedApartAreAtTheSameStepAtTheSameWallTime) {
    Screen a, b;
    b.now = a.now + 3'700'000'000 + 5'000'000;  // later, and 5 ms later in the frame
    a.frame();
    for (int i = 0; i < 222; ++i) a.now += frame_ns, a.frame();  // a's frames until b starts
    b.frame();
    b.frames_until_in_step();
    a.now = b.now;  // the same wall time, which each screen's frames reach at their own moment
    a.frame();
    EXPECT_TRUE(a.in_step());
    EXPECT_EQ(a.clock.step_index, b.clock.step_index);
    EXPECT_EQ(a.clock.sim_time, b.clock.sim_time);
}

TEST(WallSteps, AClockStepBackIsReSyncedWithinBoundedFrames) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    s.most_in_a_frame = 0;
    s.now -= 2 * ns_per_second;  // NTP steps the clock back 2 s
    s.frame();
    EXPECT_EQ(s.clock.field_generation, 2u);
    EXPECT_EQ(s.steps.resyncs, 2u);
    EXPECT_LE(s.frames_until_in_step(), 25);
    EXPECT_LE(s.most_in_a_frame, s.params.get<ParamId::wall_catch_up_steps>());
}

TEST(WallSteps, AShortStepBackIsWaitedOutWithoutAReSync) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    const std::uint64_t at = s.clock.step_index;
    s.now -= 100'000'000;  // 0.1 s: within max_hold_seconds
    int still = 0;
    while (!s.in_step()) {
        s.now += frame_ns;
        if (s.frame() == 0) ++still;
        ASSERT_LT(still, 10);
    }
    EXPECT_EQ(still, 6);  // the picture stands still for the 6 steps it had already shown
    EXPECT_EQ(s.clock.step_index, at);
    s.now += frame_ns;
    EXPECT_EQ(s.frame(), 1);  // and goes on from there
    EXPECT_TRUE(s.in_step());
    EXPECT_EQ(s.clock.field_generation, 1u);  // no re-sync: the field is still exact
}

TEST(WallSteps, AnHourForwardIsReSyncedNotFastForwarded) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    s.most_in_a_frame = 0;
    s.now += 3600 * ns_per_second;  // 216000 steps ahead
    s.frame();
    EXPECT_EQ(s.clock.field_generation, 2u);
    EXPECT_LE(s.frames_until_in_step(), 25);
    EXPECT_LE(s.most_in_a_frame, s.params.get<ParamId::wall_catch_up_steps>());
}

// Forward by less than the warm-up (a stall, a short clock step): the missed steps are caught up a
// bounded number a frame, and the field is not restarted (it stays exact).
TEST(WallSteps, AShortStepForwardIsCaughtUpExactly) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    const std::uint64_t before = s.clock.step_index;
    s.most_in_a_frame = 0;
    s.now += 5 * ns_per_second;
    const int frames = s.frames_until_in_step();
    EXPECT_EQ(s.clock.field_generation, 1u);
    EXPECT_EQ(s.most_in_a_frame, s.params.get<ParamId::wall_catch_up_steps>());
    EXPECT_EQ(frames, 6);  // 300 + 6 steps at 60 a frame
    EXPECT_EQ(s.clock.step_index, before + 300 + 6);
}

// While the output is off nothing is simulated; a minute off is more than the warm-up: waking re-syncs.
TEST(WallSteps, WakingAfterAMinuteOffReSyncs) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    s.power.on = false;
    for (int i = 0; i < 3600; ++i) {
        s.now += frame_ns;
        ASSERT_EQ(s.frame(), 0);
    }
    s.power.on = true;
    s.frame();
    EXPECT_EQ(s.clock.field_generation, 2u);
    EXPECT_LE(s.frames_until_in_step(), 25);
}

// Looks without the wave field are functions of the step: they jump to it at once, no warm-up.
TEST(WallSteps, LooksWithoutTheWaveFieldJoinAtOnce) {
    Screen s;
    s.look.scene = Scene::ocean;
    s.frame();
    EXPECT_TRUE(s.in_step());
    EXPECT_EQ(s.clock.steps_due, 0);
    // Back to the puddle: its field was not simulated meanwhile, so it warms up.
    s.look.scene = Scene::puddle;
    s.now += frame_ns;
    s.frame();
    EXPECT_EQ(s.clock.field_generation, 2u);
    EXPECT_EQ(s.clock.steps_due, s.params.get<ParamId::wall_catch_up_steps>());
}

// A pending synced change holds back its step until it is applied (systems/tuning/synced_changes.hpp).
TEST(WallSteps, AChangesStepWaitsForTheChange) {
    Screen s;
    s.frame();
    s.frames_until_in_step();
    s.steps.change_step = s.clock.step_index + 3;
    for (int i = 0; i < 5; ++i) s.now += frame_ns, s.frame();
    EXPECT_EQ(s.clock.step_index, s.steps.change_step - 1);
    s.steps.change_step = 0;  // applied
    s.now += frame_ns;
    s.frame();
    EXPECT_TRUE(s.in_step());
}

// A screen whose GPU is too slow for the wall's pace (a 1024 field on llvmpipe): each frame costs 10 ms
// plus step_ms a step it simulates. Returns the frames run until `until_ns`.
int run_costly(Screen& s, double step_ms, std::int64_t until_ns) {
    int frames = 0;
    while (s.now < until_ns) {
        const int steps = s.frame();
        s.now += 10'000'000 + std::llround(step_ms * 1e6 * steps);
        ++frames;
    }
    return frames;
}

TEST(WallSteps, AScreenTooSlowForTheWallSaysSoOnceAndStopsReSyncing) {
    const test::LogLines warnings(spdlog::level::warn);
    Screen s;
    // 25 ms a step: 40 steps a second at most, where the wall runs 60.
    run_costly(s, 25.0, start_ns + 10 * ns_per_second);
    EXPECT_TRUE(s.steps.behind_the_wall);
    EXPECT_EQ(warnings.count("this screen cannot keep the wall's pace"), 1);
    EXPECT_EQ(warnings.count(
                  fmt::format("Lower wave.resolution (now {})", s.params.get<ParamId::wave_resolution>())),
              1);
    // From then on: no re-sync, frames every 60 ms (2 steps each), each frame at the clock's step.
    const std::uint64_t resyncs = s.steps.resyncs;
    s.most_in_a_frame = 0;
    const int frames = run_costly(s, 25.0, s.now + 35 * ns_per_second);
    EXPECT_EQ(s.steps.resyncs, resyncs);
    EXPECT_LE(resyncs, 2u);  // joining (and at most one warm-up that found the screen too slow)
    EXPECT_EQ(warnings.count("this screen cannot keep the wall's pace"), 1);
    EXPECT_EQ(s.most_in_a_frame, behind_steps_per_frame);
    EXPECT_GE(frames, 35 * 1000 / 60 - 1);
    EXPECT_EQ(static_cast<std::int64_t>(s.clock.step_index), s.steps.target_step);
}

// A cheaper field (or fewer steps a second) tries the wall's pace again, and a screen that keeps it joins.
TEST(WallSteps, ACheaperFieldTriesTheWallsPaceAgain) {
    const test::LogLines lines(spdlog::level::info);
    Screen s;
    run_costly(s, 25.0, start_ns + 10 * ns_per_second);
    ASSERT_TRUE(s.steps.behind_the_wall);
    s.params.set<ParamId::wave_resolution>(128, ParamSource::CommandLine);
    const std::uint64_t generation = s.clock.field_generation;
    run_costly(s, 1.0, s.now + 30 * ns_per_second);  // 1 ms a step: 60 steps a frame gain on the clock
    EXPECT_FALSE(s.steps.behind_the_wall);
    EXPECT_EQ(lines.count("trying the wall's pace again"), 1);
    EXPECT_EQ(s.clock.field_generation, generation + 1);  // joined afresh, by a warm-up
    EXPECT_EQ(static_cast<std::int64_t>(s.clock.step_index), s.steps.target_step);
}

// A screen that keeps the pace while warming up never falls behind the wall.
TEST(WallSteps, AScreenThatKeepsThePaceNeverFallsBehind) {
    const test::LogLines warnings(spdlog::level::warn);
    Screen s;
    run_costly(s, 1.0, start_ns + 60 * ns_per_second);
    EXPECT_FALSE(s.steps.behind_the_wall);
    EXPECT_EQ(s.steps.resyncs, 1u);
    EXPECT_EQ(warnings.count("cannot keep the wall's pace"), 0);
}

// A wall that can never match is said once at start-up and by --check, whatever the clocks.
TEST(WallTimingProblem, AWallOnTheFrameClockOrAnUndampedRealtimeFieldIsNamed) {
    params::Params p;
    EXPECT_EQ(wall_timing_problem(p), std::nullopt) << "one screen, the frame clock";
    p.set<ParamId::wall_columns>(2, ParamSource::Config);
    p.set<ParamId::wall_rows>(2, ParamSource::Config);
    const auto frame = wall_timing_problem(p);
    ASSERT_TRUE(frame.has_value());
    EXPECT_NE(frame->find("a wall of 4 screens with wall.clock = \"frame\""), std::string::npos) << *frame;
    p.set<ParamId::wall_clock>(params::WallClockMode::realtime, ParamSource::Config);
    EXPECT_EQ(wall_timing_problem(p), std::nullopt);
    // The capillary field (the default) forgets through wave.drag; wave.damping is the reference's.
    p.set<ParamId::wave_damping>(1.0f, ParamSource::Config);
    EXPECT_EQ(wall_timing_problem(p), std::nullopt) << "wave.damping does not act on the capillary field";
    p.set<ParamId::wave_drag>(0.0f, ParamSource::Config);
    const auto no_drag = wall_timing_problem(p);
    ASSERT_TRUE(no_drag.has_value());
    EXPECT_NE(no_drag->find("wave.drag = 0"), std::string::npos) << *no_drag;
    p.set<ParamId::wave_model>(params::WaveModel::reference, ParamSource::Config);
    const auto undamped = wall_timing_problem(p);
    ASSERT_TRUE(undamped.has_value());
    EXPECT_NE(undamped->find("wave.damping = 1"), std::string::npos) << *undamped;
}

}  // namespace
}  // namespace puddle::systems
