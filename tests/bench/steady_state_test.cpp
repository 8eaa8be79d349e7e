// The RMS slope puddle-bench's warm-up watches (bench/steady_state.hpp), on fields with known slopes.
#include "bench/steady_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace puddle::bench {
namespace {

// A field of heights h(x, z), with a previous height that must not count.
std::vector<float> field(int n, float (*h)(int x, int z)) {
    std::vector<float> f(static_cast<std::size_t>(n) * n * 2);
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            f[2 * static_cast<std::size_t>(z * n + x)] = h(x, z);
            f[2 * static_cast<std::size_t>(z * n + x) + 1] = 100.0f * static_cast<float>(x * z);
        }
    return f;
}

TEST(SteadyState, RmsSlopeOfAFlatFieldIsZero) {
    EXPECT_EQ(rms_slope(field(8, [](int, int) { return 0.25f; }), 8), 0.0);
}

TEST(SteadyState, RmsSlopeOfARampCountsBothDirections) {
    // h = 0.5 x: 8*7 differences of 0.5 along x, 7*8 of 0 along z: sqrt(0.25 / 2).
    EXPECT_NEAR(rms_slope(field(8, [](int x, int) { return 0.5f * static_cast<float>(x); }), 8),
                std::sqrt(0.125), 1e-9);
    // A checkerboard of +-1: every neighbour differs by 2.
    EXPECT_NEAR(rms_slope(field(4, [](int x, int z) { return (x + z) % 2 ? 1.0f : -1.0f; }), 4), 2.0, 1e-9);
}

TEST(SteadyState, RmsSlopeOfATooSmallFieldIsZero) {
    EXPECT_EQ(rms_slope(field(1, [](int, int) { return 3.0f; }), 1), 0.0);
    EXPECT_EQ(rms_slope({}, 4), 0.0);
}

}  // namespace
}  // namespace puddle::bench
