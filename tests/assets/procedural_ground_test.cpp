// The procedural paving (assets/procedural_ground.hpp): the same seed gives the same bytes, the tile wraps
// without a seam (it repeats across the ground), and it is bright stones between dark joints.
#include "assets/procedural_ground.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace puddle::assets {
namespace {

double luma(const Image& img, int x, int y) {
    const std::uint8_t* p = img.pixel8(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Mean |luma difference| between column x and the column after it (wrapping at the right edge).
double column_step(const Image& img, int x) {
    double sum = 0;
    for (int y = 0; y < img.height; ++y) sum += std::abs(luma(img, (x + 1) % img.width, y) - luma(img, x, y));
    return sum / img.height;
}
double row_step(const Image& img, int y) {
    double sum = 0;
    for (int x = 0; x < img.width; ++x) sum += std::abs(luma(img, x, (y + 1) % img.height) - luma(img, x, y));
    return sum / img.width;
}

TEST(CobblestoneGround, TheSameSeedGivesTheSameBytesAndAnotherSeedDoesNot) {
    const Image a = cobblestone_ground(128, 3), b = cobblestone_ground(128, 3),
                c = cobblestone_ground(128, 4);
    ASSERT_EQ(a.width, 128);
    ASSERT_EQ(a.height, 128);
    EXPECT_EQ(a.format, PixelFormat::RGBA8);
    EXPECT_EQ(a.data, b.data);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.data.size(); i += 4) differ += a.data[i] != c.data[i];
    EXPECT_GT(differ, a.data.size() / 4 / 2) << "most pixels change with the seed";
    for (std::size_t i = 3; i < a.data.size(); i += 4) ASSERT_EQ(a.data[i], 255) << "opaque";
}

// 8 cobbles a tile edge: joints cluster near the cell boundaries (every 32 texels at 256), so the step
// across the wrap (last column to first, last row to first) is compared with the steps across the other
// cell boundaries. Fails if the cells did not wrap: the seam then steps 21 to 32 levels, the boundaries at
// most 17 (seeds 3 to 7).
TEST(CobblestoneGround, TheTileWrapsWithoutASeam) {
    const Image img = cobblestone_ground(256);
    double boundary_x = 0, boundary_y = 0;
    for (int k = 1; k < 8; ++k) {
        boundary_x = std::max(boundary_x, column_step(img, 32 * k - 1));
        boundary_y = std::max(boundary_y, row_step(img, 32 * k - 1));
    }
    EXPECT_LE(column_step(img, img.width - 1), boundary_x);
    EXPECT_LE(row_step(img, img.height - 1), boundary_y);
}

TEST(CobblestoneGround, BrightStonesBetweenDarkJoints) {
    const Image img = cobblestone_ground(256);
    int joints = 0, stones = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double l = luma(img, x, y);
            joints += l < 60;
            stones += l > 100;
        }
    const double n = img.width * img.height;
    EXPECT_GT(joints / n, 0.02) << "dark joints between the cobbles";
    EXPECT_LT(joints / n, 0.3);
    EXPECT_GT(stones / n, 0.4) << "mostly stone";
}

}  // namespace
}  // namespace puddle::assets
