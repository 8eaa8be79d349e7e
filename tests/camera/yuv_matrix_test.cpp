// Y'CbCr to R'G'B' (camera/yuv_matrix.hpp): black, white and primaries of BT.601 and BT.709 in limited
// and full range land where the standards put them.
#include "camera/yuv_matrix.hpp"

#include <gtest/gtest.h>

namespace puddle::test {
namespace {

using namespace camera;

glm::vec3 convert(const YuvToRgb& m, int y, int u, int v) {
    return m.matrix * (glm::vec3(y, u, v) / 255.0f - m.offset);
}

TEST(YuvMatrix, LimitedRangeBlackWhiteAndPrimaries) {
    const YuvToRgb bt601 = yuv_to_rgb(YuvMatrix::Bt601, false);
    const glm::vec3 white = convert(bt601, 235, 128, 128), black = convert(bt601, 16, 128, 128);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(white[c], 1.0f, 1e-4f);
        EXPECT_NEAR(black[c], 0.0f, 1e-4f);
    }
    // BT.601 limited red is (81, 90, 240).
    const glm::vec3 red = convert(bt601, 81, 90, 240);
    EXPECT_NEAR(red.r, 1.0f, 0.01f);
    EXPECT_NEAR(red.g, 0.0f, 0.01f);
    EXPECT_NEAR(red.b, 0.0f, 0.01f);
    // BT.709 limited blue is (32, 240, 118).
    const glm::vec3 blue = convert(yuv_to_rgb(YuvMatrix::Bt709, false), 32, 240, 118);
    EXPECT_NEAR(blue.r, 0.0f, 0.01f);
    EXPECT_NEAR(blue.g, 0.0f, 0.01f);
    EXPECT_NEAR(blue.b, 1.0f, 0.01f);
}

TEST(YuvMatrix, FullRangeUsesEveryCode) {
    const YuvToRgb m = yuv_to_rgb(YuvMatrix::Bt601, true);
    EXPECT_NEAR(convert(m, 255, 128, 128).g, 1.0f, 1e-4f);
    EXPECT_NEAR(convert(m, 0, 128, 128).g, 0.0f, 1e-4f);
    // Full-range (JPEG) BT.601 green is (150, 44, 21).
    const glm::vec3 green = convert(m, 150, 44, 21);
    EXPECT_NEAR(green.r, 0.0f, 0.01f);
    EXPECT_NEAR(green.g, 1.0f, 0.01f);
    EXPECT_NEAR(green.b, 0.0f, 0.01f);
}
}  // namespace
}  // namespace puddle::test
