// Time for shaders (render/shader_phase.hpp): phases, lattice shifts and repetitions stay small, exact
// and continuous at any uptime, including past 2^31 and 2^32 cells.
#include "render/shader_phase.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace puddle::render {
namespace {

constexpr double two_pi = 6.283185307179586;

TEST(PeriodicPhase, IsRateTimesSecondsModuloThePeriod) {
    EXPECT_FLOAT_EQ(periodic_phase(10, 0.25, 2), 0.5f);  // 2.5 mod 2
    EXPECT_FLOAT_EQ(periodic_phase(1, -1, 4), 3.0f);     // negative rates wrap upward
    EXPECT_FLOAT_EQ(periodic_phase(8, 0.5, 4), 0.0f);    // a whole number of periods
    EXPECT_GE(periodic_phase(-1e-17, 1, 1), 0.0f)
        << "a hair below a multiple rounds to 0, never to the period";
    EXPECT_LT(periodic_phase(-1e-17, 1, 1), 1.0f);
}

// At about 3 years of uptime a float of seconds has steps of 8 s; the phase still advances by exactly
// rate * dt from one frame to the next (within a float's precision of a value below the period).
TEST(PeriodicPhase, StaysContinuousAtLongUptimes) {
    const double rate = 1.7, dt = 1.0 / 60;
    for (const double t : {1e3, 1e8, 4096.0 * 1e5}) {
        const double a = periodic_phase(t, rate, two_pi), b = periodic_phase(t + dt, rate, two_pi);
        double step = b - a;
        if (step < 0) step += two_pi;
        EXPECT_NEAR(step, rate * dt, 2e-6) << "at " << t << " s";
        EXPECT_GE(a, 0);
        EXPECT_LT(a, two_pi);
    }
}

// cells + fraction is rate * seconds; consecutive whole cells differ by one in uint32 arithmetic, also
// where a signed 32-bit count would overflow (2^31) and where the uint wraps (2^32).
TEST(LatticeShift, SplitsWholeCellsModulo2To32AndTheFraction) {
    const LatticeShift s = lattice_shift(10, 0.35);  // 3.5 cells
    EXPECT_EQ(s.cells, 3);
    EXPECT_FLOAT_EQ(s.fraction, 0.5f);
    for (const double cells : {2147483647.0, 4294967295.0, 1e12 + 0.25}) {
        const LatticeShift a = lattice_shift(cells, 1.0), b = lattice_shift(cells + 1, 1.0);
        EXPECT_EQ(static_cast<std::uint32_t>(b.cells) - static_cast<std::uint32_t>(a.cells), 1u) << cells;
        EXPECT_FLOAT_EQ(a.fraction, b.fraction) << cells;
        EXPECT_GE(a.fraction, 0.0f);
        EXPECT_LT(a.fraction, 1.0f);
    }
    const LatticeShift back = lattice_shift(1, -2.5);  // -2.5 cells: floor -3, fraction 0.5
    EXPECT_EQ(static_cast<std::uint32_t>(back.cells), static_cast<std::uint32_t>(-3));
    EXPECT_FLOAT_EQ(back.fraction, 0.5f);
}

TEST(RepetitionAt, CountsWholePeriodsFromTheOffsetAndTheAgeWithinOne) {
    const Repetition r = repetition_at(7.5, 2.0, 0.25);  // 3.75 + 0.25 = 4 periods: the 5th starts now
    EXPECT_EQ(r.index, 4u);
    EXPECT_FLOAT_EQ(r.age, 0.0f);
    const Repetition mid = repetition_at(7.0, 2.0, 0.0);  // 3.5 periods
    EXPECT_EQ(mid.index, 3u);
    EXPECT_FLOAT_EQ(mid.age, 1.0f);
    // 2^32 periods in: the index wraps to 0 as a shader's uint would, the age is unaffected.
    const Repetition wrapped = repetition_at(4294967296.0 * 0.5 + 0.1, 0.5, 0.0);
    EXPECT_EQ(wrapped.index, 0u);
    EXPECT_NEAR(wrapped.age, 0.1f, 1e-6f);
}

}  // namespace
}  // namespace puddle::render
