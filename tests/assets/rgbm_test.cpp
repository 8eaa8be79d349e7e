// RGBM keeps HDR radiance to about a percent of its brightest channel up to 16, saturates past it, and
// blends more like radiance than a shared exponent when two texels are averaged.
#include "assets/rgbm.hpp"

#include <gtest/gtest.h>

namespace puddle::assets {
namespace {

TEST(Rgbm, RoundTripKeepsRadianceWithinAPercentOfTheBrightestChannel) {
    for (float v : {0.004f, 0.0123f, 0.2158f, 0.5f, 1.0f, 1.7f, 11.81f, 16.0f}) {
        const float rgb[3] = {v, 0.5f * v, 0.25f * v};
        const auto back = decode_rgbm(encode_rgbm(rgb).data());
        // 8 bits of colour under the smallest 8-bit scale that holds it: darks lose most, in absolute terms
        // little.
        const float tolerance = std::max(0.01f * v, 0.5f * rgbm_range / 255.0f / 255.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back[c], rgb[c], tolerance) << "value " << v << " channel " << c;
    }
}

TEST(Rgbm, BlackStaysBlackAndBeyondTheRangeSaturates) {
    const float black[3] = {0, 0, 0};
    EXPECT_EQ(decode_rgbm(encode_rgbm(black).data())[0], 0.0f);
    const float sun[3] = {5000.0f, 8.0f, 0.0f};
    const auto t = encode_rgbm(sun);
    EXPECT_EQ(t[3], 255);
    EXPECT_FLOAT_EQ(decode_rgbm(t.data())[0], rgbm_range);
    EXPECT_NEAR(decode_rgbm(t.data())[1], 8.0f, 0.05f);
}

TEST(Rgbm, AveragingTwoTexelsKeepsMoreLightThanASharedExponentWould) {
    // What a bilinear filter does halfway between a lit window (10) and a dark wall (0.006): the true
    // average is 5; RGBM gives over half of it, where RGBE's interpolated exponent gives about 0.25.
    const float window[3] = {10.0f, 8.0f, 5.0f}, wall[3] = {0.006f, 0.006f, 0.008f};
    const auto a = encode_rgbm(window), b = encode_rgbm(wall);
    std::array<std::uint8_t, 4> mid{};
    for (int c = 0; c < 4; ++c) mid[c] = static_cast<std::uint8_t>((a[c] + b[c] + 1) / 2);
    const float blended = decode_rgbm(mid.data())[0];
    EXPECT_GT(blended, 2.5f);
    EXPECT_LT(blended, 5.0f);
}

TEST(Rgbm, ImagesEncodeTexelByTexel) {
    Image linear = Image::make(2, 1, PixelFormat::RGBA32F);
    linear.pixelf(1, 0)[2] = 3.0f;
    const Image encoded = encode_rgbm(linear);
    ASSERT_EQ(encoded.format, PixelFormat::RGBA8);
    EXPECT_NEAR(decode_rgbm(encoded.pixel8(1, 0))[2], 3.0f, 0.03f);
    EXPECT_EQ(decode_rgbm(encoded.pixel8(0, 0))[2], 0.0f);
}

}  // namespace
}  // namespace puddle::assets
