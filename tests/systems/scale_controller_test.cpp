// The adaptive scale's controller under synthetic loads: a frame costs fixed + per_pixel * scale^2 seconds
// (the scaled canvas shades scale^2 of the pixels), and the clock advances by each frame's time, so these
// tests run in microseconds and repeat exactly.
#include "systems/output/scale_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>

namespace puddle::systems {
namespace {

constexpr double budget_60 = 1.0 / 60;

struct Load {
    double fixed_s, per_pixel_s;
    double at(float scale) const { return fixed_s + per_pixel_s * scale * scale; }
};

// Drives the controller with frames of `load` for `seconds` of simulated time; returns how many times
// the scale changed and the shortest gap between two changes.
struct RunResult {
    int changes = 0;
    int settled = 0;
    double shortest_gap_s = 1e9;
    float lowest = 1;
};
struct Sim {
    ScaleController controller;
    double now = 0;
    double last_change = -1;
    enum class Measure { frame, gpu, vsync_frame } measure = Measure::frame;

    RunResult run(const Load& load, double seconds) {
        RunResult r;
        r.lowest = controller.scale();
        const double end = now + seconds;
        while (now < end) {
            const double cost = load.at(controller.scale());
            double frame = cost;
            std::optional<double> gpu;
            if (measure == Measure::gpu) gpu = cost;
            if (measure != Measure::frame)  // a display that waits for vblank: whole refresh periods
                frame = std::ceil(cost / budget_60 - 1e-9) * budget_60;
            now += frame;
            const ScaleUpdate u = controller.add_frame(now, frame, gpu);
            EXPECT_EQ(u.scale, controller.scale());
            if (u.changed) {
                ++r.changes;
                if (last_change >= 0) r.shortest_gap_s = std::min(r.shortest_gap_s, now - last_change);
                last_change = now;
            }
            r.settled += u.settled ? 1 : 0;
            r.lowest = std::min(r.lowest, controller.scale());
        }
        return r;
    }
};

ScaleTuning tuning_60() {
    return {.target_fps = 60, .min_scale = 0.5f, .max_scale = 1.0f};
}

// 30 ms at full scale: twice the 16.7 ms budget.
constexpr Load slow{.fixed_s = 0.002, .per_pixel_s = 0.028};

TEST(ScaleController, ASlowLoadConvergesBelowOneAndMeetsTheTargetWithin15Seconds) {
    Sim sim{ScaleController(tuning_60())};
    const RunResult r = sim.run(slow, 15.0);
    EXPECT_LT(sim.controller.scale(), 1.0f);
    EXPECT_LE(slow.at(sim.controller.scale()), budget_60);  // meets 60 fps
    EXPECT_GE(sim.controller.scale(), 0.5f);
    EXPECT_GE(r.shortest_gap_s, 3.0);  // at most one change per hold_s
    EXPECT_EQ(r.settled, 1);           // one "settled" once it stopped moving
    EXPECT_EQ(sim.controller.last_source(), CostSource::frame);
}

TEST(ScaleController, ASteadyLoadKeepsTheScaleForTenMinutes) {
    Sim sim{ScaleController(tuning_60())};
    sim.run(slow, 15.0);
    const float settled = sim.controller.scale();
    const RunResult r = sim.run(slow, 600.0);
    EXPECT_EQ(r.changes, 0);
    EXPECT_EQ(sim.controller.scale(), settled);
}

TEST(ScaleController, ComesBackToFullScaleWithin30SecondsWhenTheLoadGoes) {
    Sim sim{ScaleController(tuning_60())};
    sim.run(slow, 15.0);
    ASSERT_LT(sim.controller.scale(), 1.0f);
    const RunResult r = sim.run({.fixed_s = 0.002, .per_pixel_s = 0.006}, 30.0);
    EXPECT_EQ(sim.controller.scale(), 1.0f);
    EXPECT_GE(r.shortest_gap_s, 3.0);
    EXPECT_EQ(r.settled, 1);
}

TEST(ScaleController, NeverGoesBelowMinScale) {
    ScaleTuning t = tuning_60();
    t.min_scale = 0.62;  // off the 0.05 grid of the steps: the last step down stops at it
    Sim sim{ScaleController(t)};
    const RunResult r = sim.run({.fixed_s = 0.002, .per_pixel_s = 0.2}, 120.0);  // 200 ms: no scale fits
    EXPECT_EQ(sim.controller.scale(), 0.62f);
    EXPECT_EQ(r.lowest, 0.62f);
    EXPECT_EQ(r.settled, 1);  // settles at the floor, said once
}

// A load no scale fits: the windows run at the floor miss the target, and say so; the windows on the way
// down do not (a lower scale was still to try). A load that fits at the floor never says it.
TEST(ScaleController, AWindowAtTheFloorThatMissesSaysNoScaleHoldsTheTarget) {
    for (const bool fits : {false, true}) {
        SCOPED_TRACE(fits);
        Sim sim{ScaleController(tuning_60())};
        const Load load =
            fits ? Load{.fixed_s = 0.002, .per_pixel_s = 0.04} : Load{.fixed_s = 0.002, .per_pixel_s = 0.2};
        int short_windows = 0, windows = 0;
        bool short_above_floor = false;
        for (double now = 0; now < 60;) {
            const float scale = sim.controller.scale();
            const double frame = load.at(scale);
            now += frame;
            const ScaleUpdate u = sim.controller.add_frame(now, frame, std::nullopt);
            windows += u.window_ended ? 1 : 0;
            short_windows += u.short_at_floor ? 1 : 0;
            if (u.short_at_floor && scale > 0.5f) short_above_floor = true;
        }
        EXPECT_GT(windows, 10);
        EXPECT_FALSE(short_above_floor);
        if (fits)
            EXPECT_EQ(short_windows, 0) << "0.04 s at full scale is 0.01 s at 0.5: it holds 60 fps";
        else
            EXPECT_GT(short_windows, 5)
                << "200 ms at full scale, 52 ms at 0.5: every window at the floor is short";
    }
}

// A timer that misses the work (llvmpipe ends the query before it runs a single pass's draws): GPU times
// of 0.2 ms while frames take twice the budget. The frame times decide, and the scale comes down.
TEST(ScaleController, GpuTimesFarUnderSlowFramesAreNotTrusted) {
    ScaleController c(tuning_60());
    double now = 0;
    for (int frame = 0; frame < 600; ++frame) {
        const double cost = slow.at(c.scale());
        now += cost;
        c.add_frame(now, cost, 0.0002);
    }
    EXPECT_LT(c.scale(), 1.0f);
    EXPECT_EQ(c.last_source(), CostSource::frame);
    EXPECT_LE(slow.at(c.scale()), 1.1 * budget_60);
    // And it stays: the timer's false headroom does not take the scale back up.
    const float settled = c.scale();
    int changes = 0;
    for (int frame = 0; frame < 3000; ++frame) {
        const double cost = slow.at(c.scale());
        now += cost;
        changes += c.add_frame(now, cost, 0.0002).changed ? 1 : 0;
    }
    EXPECT_EQ(changes, 0);
    EXPECT_EQ(c.scale(), settled);
}

TEST(ScaleController, StepsAreSmall) {
    Sim sim{ScaleController(tuning_60())};
    float previous = sim.controller.scale();
    for (int i = 0; i < 2000; ++i) {
        sim.run(slow, 0.1);
        EXPECT_LE(std::abs(sim.controller.scale() - previous), 0.1f + 1e-6f);
        previous = sim.controller.scale();
    }
}

TEST(ScaleController, GpuTimesShowHeadroomBehindVblank) {
    // Frames are whole refresh periods; the GPU times are the load: down, then up when it goes, without
    // waiting to try.
    Sim sim{ScaleController(tuning_60())};
    sim.measure = Sim::Measure::gpu;
    sim.run(slow, 15.0);
    EXPECT_LT(sim.controller.scale(), 1.0f);
    EXPECT_LE(slow.at(sim.controller.scale()), budget_60);
    EXPECT_EQ(sim.controller.last_source(), CostSource::gpu);
    const RunResult r = sim.run({.fixed_s = 0.002, .per_pixel_s = 0.006}, 30.0);
    EXPECT_EQ(sim.controller.scale(), 1.0f);
    EXPECT_EQ(r.settled, 1);
}

TEST(ScaleController, BehindVblankFrameTimesTryUpRarelyAndBackOff) {
    // Frame times only, whole refresh periods: at 0.8 the frame fits (15.9 ms), at 0.85 it does not
    // (17.4 ms, two periods). The scale tries a step up after 10 s, then waits 20, 40, 80, 160 s.
    Sim sim{ScaleController(tuning_60())};
    sim.measure = Sim::Measure::vsync_frame;
    constexpr Load edge{.fixed_s = 0.002, .per_pixel_s = 0.0217};
    sim.run(edge, 60.0);
    const RunResult r = sim.run(edge, 600.0);
    EXPECT_LE(sim.controller.scale(), 0.85f);
    EXPECT_GE(sim.controller.scale(), 0.75f);
    // Each try is one step up and one down: in 600 s at most the tries at 160 s apart plus the doubling.
    EXPECT_LE(r.changes, 10);
    EXPECT_GE(r.changes, 2);  // it does try: a load that went would be noticed
}

TEST(ScaleController, StallsAreNotLoad) {
    Sim sim{ScaleController(tuning_60())};
    for (int i = 0; i < 100; ++i) {
        sim.now += 2.0;  // output off, a start-up compile: frames seconds long
        EXPECT_FALSE(sim.controller.add_frame(sim.now, 2.0, std::nullopt).changed);
    }
    EXPECT_EQ(sim.controller.scale(), 1.0f);
}

}  // namespace
}  // namespace puddle::systems
