// Image helpers: sRGB <-> linear conversions follow IEC 61966-2-1, and halving averages 2x2 blocks.
#include "assets/image.hpp"

#include <gtest/gtest.h>

namespace puddle::assets {
namespace {

TEST(Image, SrgbDecodesToLinearAndBack) {
    Image srgb = Image::make(3, 1);
    const std::uint8_t values[3] = {0, 128, 255};
    for (int x = 0; x < 3; ++x) srgb.pixel8(x, 0)[0] = values[x], srgb.pixel8(x, 0)[3] = 255;
    const Image linear = to_linear_float(srgb);
    ASSERT_EQ(linear.format, PixelFormat::RGBA32F);
    EXPECT_FLOAT_EQ(linear.pixelf(0, 0)[0], 0.0f);
    EXPECT_NEAR(linear.pixelf(1, 0)[0], 0.21586f, 1e-5f);
    EXPECT_FLOAT_EQ(linear.pixelf(2, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(linear.pixelf(1, 0)[3], 1.0f);
    const Image back = to_srgb8(linear);
    for (int x = 0; x < 3; ++x) EXPECT_EQ(back.pixel8(x, 0)[0], values[x]);
}

TEST(Image, ToSrgbClampsRadianceBeyondWhite) {
    Image hdr = Image::make(1, 1, PixelFormat::RGBA32F);
    hdr.pixelf(0, 0)[0] = 12.0f;
    hdr.pixelf(0, 0)[1] = -1.0f;
    const Image out = to_srgb8(hdr);
    EXPECT_EQ(out.pixel8(0, 0)[0], 255);
    EXPECT_EQ(out.pixel8(0, 0)[1], 0);
}

TEST(Image, HalvingAveragesBlocks) {
    Image f = Image::make(4, 2, PixelFormat::RGBA32F);
    f.pixelf(0, 0)[0] = 4.0f;  // one bright texel in the first 2x2 block
    Image half = halve(f);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_FLOAT_EQ(half.pixelf(0, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(half.pixelf(1, 0)[0], 0.0f);
    Image b = Image::make(2, 2);
    b.pixel8(0, 0)[2] = 255, b.pixel8(1, 1)[2] = 1;
    EXPECT_EQ(halve(b).pixel8(0, 0)[2], 64);  // (255 + 1 + 2) / 4, rounded
    EXPECT_EQ(halve(Image::make(1, 1)).width, 1) << "never below one texel";
}

}  // namespace
}  // namespace puddle::assets
