// Tests for systems/clock/frame_clock.hpp: the fixed-step accumulator and the double-precision sim time.
#include "systems/clock/frame_clock.hpp"

#include <gtest/gtest.h>

namespace puddle::systems {
namespace {

using params::ParamId;
using params::ParamSource;

// Runs one frame of `dt` seconds through the input-stage system; returns the steps due.
int frame(FrameClock& clock, const params::Params& p, double dt) {
    frame_clock_system(ecs::FrameTime{dt}, p, clock);
    return clock.steps_due;
}

TEST(FrameClock, StepSecondsFollowsTheParameter) {
    params::Params p;
    FrameClock clock;
    frame(clock, p, 0.0);
    EXPECT_DOUBLE_EQ(clock.step_seconds, 1.0 / 60.0);
    EXPECT_EQ(clock.steps_due, 0);
    ASSERT_TRUE(p.set(ParamId::wave_steps_per_second, 120.0f, ParamSource::CommandLine));
    frame(clock, p, 0.0);
    EXPECT_DOUBLE_EQ(clock.step_seconds, 1.0 / 120.0);
}

TEST(FrameClock, ThirtyFpsGivesTwoStepsEachFrame) {
    const params::Params p;  // wave.steps_per_second = 60
    FrameClock clock;
    for (int i = 0; i < 300; ++i) ASSERT_EQ(frame(clock, p, 1.0 / 30.0), 2) << "frame " << i;
    EXPECT_EQ(clock.dropped_steps, 0u);
}

TEST(FrameClock, SixtyFpsGivesOneStepEachFrame) {
    const params::Params p;
    FrameClock clock;
    for (int i = 0; i < 600; ++i) ASSERT_EQ(frame(clock, p, 1.0 / 60.0), 1) << "frame " << i;
}

TEST(FrameClock, OneHundredFortyFourFpsOverTwoSecondsGivesExactly120Steps) {
    const params::Params p;
    FrameClock clock;
    int total = 0;
    for (int i = 0; i < 288; ++i) {
        const int due = frame(clock, p, 1.0 / 144.0);
        EXPECT_GE(due, 0);
        EXPECT_LE(due, 1) << "frame " << i;
        total += due;
    }
    EXPECT_EQ(total, 120);
    EXPECT_EQ(clock.dropped_steps, 0u);
}

TEST(FrameClock, StepCountDoesNotDependOnTheFrameRate) {
    const params::Params p;
    for (int fps : {24, 25, 30, 50, 59, 60, 75, 90, 120, 144, 165, 240}) {
        FrameClock clock;
        int total = 0;
        for (int i = 0; i < fps * 10; ++i) total += frame(clock, p, 1.0 / fps);
        EXPECT_EQ(total, 600) << fps << " fps over 10 s";
    }
}

TEST(FrameClock, DoubledStepRateDoublesTheSteps) {
    params::Params p;
    ASSERT_TRUE(p.set(ParamId::wave_steps_per_second, 120.0f, ParamSource::Config));
    FrameClock clock;
    EXPECT_EQ(frame(clock, p, 1.0 / 30.0), 4);
    EXPECT_EQ(frame(clock, p, 1.0 / 60.0), 2);
}

TEST(FrameClock, LeftoverTimeCarriesOver) {
    const params::Params p;
    FrameClock clock;
    EXPECT_EQ(frame(clock, p, 0.010), 0);  // less than a step
    EXPECT_NEAR(clock.accumulator, 0.010, 1e-12);
    EXPECT_EQ(frame(clock, p, 0.010), 1);  // 20 ms: one step, 3.33 ms left
    EXPECT_NEAR(clock.accumulator, 0.020 - 1.0 / 60.0, 1e-12);
}

TEST(FrameClock, HugeFrameIsCappedAndCountedAsDropped) {
    const params::Params p;
    FrameClock clock;
    ASSERT_EQ(clock.max_steps_per_frame, 16);
    EXPECT_EQ(frame(clock, p, 10.0), 16);  // 600 steps were due
    EXPECT_EQ(clock.dropped_steps, 584u);
    // The dropped time is gone: the next normal frame is normal again.
    EXPECT_EQ(frame(clock, p, 1.0 / 60.0), 1);
    EXPECT_EQ(clock.dropped_steps, 584u);
    EXPECT_EQ(frame(clock, p, 1.0), 16);
    EXPECT_EQ(clock.dropped_steps, 584u + 44u);
}

TEST(FrameClock, CapFollowsMaxStepsPerFrame) {
    const params::Params p;
    FrameClock clock;
    clock.max_steps_per_frame = 4;
    EXPECT_EQ(frame(clock, p, 0.5), 4);  // 30 due
    EXPECT_EQ(clock.dropped_steps, 26u);
}

TEST(FrameClock, BeginStepAdvancesTimeAndIndex) {
    FrameClock clock;
    clock.step_seconds = 0.25;
    begin_step_system(clock);
    EXPECT_EQ(clock.step_index, 1u);
    EXPECT_EQ(clock.sim_time, 0.25);
    begin_step_system(clock);
    EXPECT_EQ(clock.step_index, 2u);
    EXPECT_EQ(clock.sim_time, 0.5);
}

// A signage screen runs for days: after 10 million steps (46 hours at 60 steps/s) the simulated time
// must still be exact to a microsecond, or ripples drift and drops fire at the wrong phase.
TEST(FrameClock, SimTimeStaysPreciseOverTenMillionSteps) {
    FrameClock clock;
    clock.step_seconds = 1.0 / 60.0;
    constexpr std::uint64_t steps = 10'000'000;
    for (std::uint64_t i = 0; i < steps; ++i) begin_step_system(clock);
    EXPECT_EQ(clock.step_index, steps);
    EXPECT_NEAR(clock.sim_time, 166666.66666666666, 1e-6);
}

// While the output is off the due steps are counted, not run: sim_time keeps up with the frames' time.
TEST(FrameClock, StepsAreHeldWhileTheOutputIsOffAndTimeGoesOn) {
    const params::Params p;  // 60 steps per second
    FrameClock clock;
    const OutputPower off{.on = false};
    for (int i = 0; i < 30; ++i) {
        frame(clock, p, 1.0 / 30);
        hold_steps_while_off(off, clock);
        EXPECT_EQ(clock.steps_due, 0);
    }
    EXPECT_EQ(clock.step_index, 60u);
    EXPECT_NEAR(clock.sim_time, 1.0, 1e-9);
    const OutputPower on{};
    frame(clock, p, 1.0 / 30);
    hold_steps_while_off(on, clock);
    EXPECT_EQ(clock.steps_due, 2) << "on again, steps run from the current time";
}

}  // namespace
}  // namespace puddle::systems
