// RGB to JPEG (camera/mjpeg_encoder.hpp), the decoder's twin: a picture of known content comes back
// through MjpegDecoder within JPEG's loss, with its size; sizes that do not fit the pixels give nothing.
#include "camera/mjpeg_encoder.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "camera/mjpeg_decoder.hpp"

namespace puddle::camera {
namespace {

// Left half red, right half blue, a smooth green ramp from top to bottom: colours JPEG keeps well away
// from the middle seam.
std::vector<std::uint8_t> picture(int width, int height) {
    std::vector<std::uint8_t> rgb;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool left = x < width / 2;
            rgb.push_back(left ? 220 : 20);
            rgb.push_back(static_cast<std::uint8_t>(40 + 160 * y / (height - 1)));
            rgb.push_back(left ? 20 : 220);
        }
    return rgb;
}

TEST(MjpegEncoder, APictureComesBackThroughTheDecoderWithinJpegLoss) {
    const int w = 64, h = 48;
    const std::vector<std::uint8_t> rgb = picture(w, h);
    const std::vector<std::byte> jpeg = encode_jpeg(rgb, w, h, 95);
    ASSERT_GT(jpeg.size(), 4u);
    EXPECT_EQ(jpeg[0], std::byte{0xff});  // SOI
    EXPECT_EQ(jpeg[1], std::byte{0xd8});
    MjpegDecoder decoder;
    ASSERT_TRUE(decoder.decode(jpeg, w, h));
    EXPECT_FALSE(decoder.decode(jpeg, w * 2, h)) << "the size is in the frame";
    ASSERT_TRUE(decoder.decode(jpeg, w, h));
    const auto rgba = decoder.rgba();
    ASSERT_EQ(rgba.size(), std::size_t(w) * h * 4);
    int worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (std::abs(x - w / 2) < 4) continue;  // chroma is subsampled across the seam
            for (int c = 0; c < 3; ++c) {
                const int got = std::to_integer<int>(rgba[(std::size_t(y) * w + x) * 4 + c]);
                worst = std::max(worst, std::abs(got - rgb[(std::size_t(y) * w + x) * 3 + c]));
            }
        }
    EXPECT_LE(worst, 12) << "quality 95";
}

TEST(MjpegEncoder, LowerQualityGivesFewerBytes) {
    const std::vector<std::uint8_t> rgb = picture(64, 48);
    EXPECT_LT(encode_jpeg(rgb, 64, 48, 20).size(), encode_jpeg(rgb, 64, 48, 95).size());
}

TEST(MjpegEncoder, SizesThatDoNotFitThePixelsGiveNothing) {
    const std::vector<std::uint8_t> rgb = picture(8, 8);
    EXPECT_TRUE(encode_jpeg(rgb, 16, 8, 90).empty());
    EXPECT_TRUE(encode_jpeg(rgb, 0, 8, 90).empty());
    EXPECT_FALSE(encode_jpeg(rgb, 8, 8, 90).empty());
}

}  // namespace
}  // namespace puddle::camera
