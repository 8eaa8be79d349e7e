// Tests for systems/clock/wall_clock.hpp: wave steps from integer nanoseconds, the change boundary, the
// warm-up's residual and the kernel's clock status.
#include "systems/clock/wall_clock.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace puddle::systems {
namespace {

// floor(ns * rate / 1e9) for a whole rate and ns >= 0, exactly, in integers: whole seconds times the rate,
// plus the steps of the rest of a second.
std::int64_t exact_step(std::int64_t ns, std::int64_t rate) {
    return ns / ns_per_second * rate + ns % ns_per_second * rate / ns_per_second;
}

// The first nanosecond of step `step` at a whole rate: ceil(step * 1e9 / rate), in integers.
std::int64_t step_start(std::int64_t step, std::int64_t rate) {
    const std::int64_t seconds = step / rate, rest = step % rate;
    return seconds * ns_per_second + (rest * ns_per_second + rate - 1) / rate;
}

TEST(WallClock, StepAtIsExactForWholeRatesAtTodaysTimes) {
    std::mt19937_64 random(20);
    std::uniform_int_distribution<std::int64_t> times(1'700'000'000LL * ns_per_second,
                                                      2'100'000'000LL * ns_per_second);
    for (std::int64_t rate : {10, 60, 120, 480}) {
        for (int i = 0; i < 100000; ++i) {
            const std::int64_t ns = times(random);
            ASSERT_EQ(step_at(ns, static_cast<double>(rate)), exact_step(ns, rate)) << ns << " at " << rate;
        }
        // The first nanosecond of a step is in it, the last one before it is not.
        const std::int64_t step = exact_step(1'764'547'200LL * ns_per_second, rate) + 7;
        const std::int64_t start = step_start(step, rate);
        EXPECT_EQ(step_at(start, static_cast<double>(rate)), step);
        EXPECT_EQ(step_at(start - 1, static_cast<double>(rate)), step - 1);
    }
}

TEST(WallClock, StepAtFollowsAFractionalRate) {
    const double rate = static_cast<double>(59.94f);
    for (std::int64_t s : {1'764'547'200LL, 2'000'000'000LL}) {
        const std::int64_t ns = s * ns_per_second + 123'456'789;
        const long double exact = static_cast<long double>(ns) * rate / 1e9L;
        EXPECT_EQ(step_at(ns, rate), static_cast<std::int64_t>(std::floor(exact))) << ns;
    }
}

TEST(WallClock, ChangeBoundaryIsTheNextWholePeriodPlusOne) {
    const std::int64_t noon = 1'764'590'400LL * ns_per_second;  // 2025-12-01 12:00:00 UTC
    EXPECT_EQ(change_boundary(noon + 300'000'000, 1.0), noon + 2 * ns_per_second);
    EXPECT_EQ(change_boundary(noon + 999'999'999, 1.0), noon + 2 * ns_per_second);
    EXPECT_EQ(change_boundary(noon, 1.0), noon + 2 * ns_per_second);
    EXPECT_EQ(change_boundary(noon + 1, 1.0), noon + 2 * ns_per_second);
    EXPECT_EQ(change_boundary(noon + ns_per_second, 1.0), noon + 3 * ns_per_second);
    EXPECT_EQ(change_boundary(noon + 7 * ns_per_second, 5.0), noon + 15 * ns_per_second);
}

// The residual docs/video-walls.md and wall.warmup's help state: 1e-4 at the default damping and warm-up.
TEST(WallClock, WarmUpResidualIsDampingToTheHalfSteps) {
    EXPECT_NEAR(warmup_residual(0.985, 1200), std::exp(600 * std::log(0.985)), 1e-15);
    EXPECT_LT(warmup_residual(0.985, 1200), 1.2e-4);
    EXPECT_GT(warmup_residual(0.985, 1200), 1.1e-4);
    EXPECT_EQ(warmup_residual(1.0, 1200), 1.0);  // an undamped field forgets nothing
}

TEST(WallClock, TheKernelsClockStatusIsReadAndDescribed) {
    const ClockSync sync = read_clock_sync();
    EXPECT_TRUE(sync.problem.empty()) << sync.problem;  // adjtimex with modes 0 needs no privilege
    EXPECT_GE(sync.maximum_error_us, 0);
    const std::string text = describe(sync);
    EXPECT_EQ(text.find(sync.synchronised ? "synchronised, estimated error" : "NOT synchronised"), 0u)
        << text;
    EXPECT_EQ(describe(ClockSync{.synchronised = true, .estimated_error_us = 120, .maximum_error_us = 8400}),
              "synchronised, estimated error 0.120 ms (maximum 8.4 ms)");
}

TEST(WallClock, SystemWallNanosecondsAreTheRealTimeClock) {
    const auto before = static_cast<std::int64_t>(std::time(nullptr));
    const std::int64_t ns = system_wall_ns();
    EXPECT_GE(ns / ns_per_second, before);
    EXPECT_LE(ns / ns_per_second, before + 1);
}

}  // namespace
}  // namespace puddle::systems
