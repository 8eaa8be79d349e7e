// upload_next_band (render/banded_upload.hpp) on a real context: each call uploads the whole rows that fit
// in the texel budget (at least one), starting where the last call stopped, so the bands cover every row
// once and the last band is short; a budget under one row (zero, negative) still moves a row a call and a
// huge one takes the rest at once. After every call the texture is read back: exactly the rows up to
// next_row hold the image, the others still the clear. 8-bit and float images (a texel's bytes differ),
// a mip level and a cube face.
#include "render/banded_upload.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <cstring>
#include <vector>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::render {
namespace {

using assets::Image;
using assets::PixelFormat;

// Texel (x, y) holds (x + 1, y + 1, 7, 255) (as floats: the same numbers / 255), never the zero clear,
// so a row in the wrong place or a row missing shows.
Image numbered(int width, int height, PixelFormat format) {
    Image image = Image::make(width, height, format);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float texel[4] = {float(x + 1), float(y + 1), 7, 255};
            if (format == PixelFormat::RGBA8)
                for (int c = 0; c < 4; ++c) image.pixel8(x, y)[c] = static_cast<std::uint8_t>(texel[c]);
            else
                for (int c = 0; c < 4; ++c) image.pixelf(x, y)[c] = texel[c] / 255.0f;
        }
    return image;
}

class BandedUploadTest : public test::DeviceFixture {
protected:
    gpu::Texture make(gpu::TextureKind kind, gpu::TextureFormat format, int width, int height,
                      int levels = 1) {
        auto t = device_->create_texture({.label = "banded",
                                          .kind = kind,
                                          .format = format,
                                          .width = width,
                                          .height = height,
                                          .mip_levels = levels,
                                          .render_target = true});
        EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message);
        if (!t) return {};
        const int faces = kind == gpu::TextureKind::Cube ? 6 : 1;
        for (int face = 0; face < faces; ++face)
            for (int level = 0; level < levels; ++level)
                device_->begin_pass(
                    {.label = "zero",
                     .target = {.texture = &*t,
                                .size = {std::max(1, width >> level), std::max(1, height >> level)},
                                .face = face,
                                .level = level},
                     .load = gpu::LoadOp::Clear,
                     .clear = {0, 0, 0, 0}});
        return std::move(t).value();
    }

    // Level 0 (of `face`) as floats, rows in GL order: row 0 is the image's first row.
    std::vector<float> level0(const gpu::Texture& t, int face = 0) { return device_->read_texture(t, face); }

    // How many rows, from the first, hold `image` in `texels` (4 floats a texel, image rows in order); -1
    // when a later row is not all zero (written out of turn).
    static int rows_holding(const Image& image, const std::vector<float>& texels) {
        int done = 0;
        while (done < image.height && row_is(image, texels, done, true)) ++done;
        for (int y = done; y < image.height; ++y)
            if (!row_is(image, texels, y, false)) return -1;
        return done;
    }
    static bool row_is(const Image& image, const std::vector<float>& texels, int y, bool uploaded) {
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const float want = !uploaded                            ? 0.0f
                                   : image.format == PixelFormat::RGBA8 ? image.pixel8(x, y)[c] / 255.0f
                                                                        : image.pixelf(x, y)[c];
                if (texels[(std::size_t(y) * image.width + x) * 4 + c] != want) return false;
            }
        return true;
    }

    // Calls upload_next_band until it says done (at most 100 calls); per call, next_row and the rows that
    // the read-back shows uploaded, which must be the same.
    std::vector<int> bands(gpu::Texture& t, const Image& image, long budget, int face = 0) {
        std::vector<int> after;
        int next_row = 0;
        for (int call = 0; call < 100; ++call) {
            const bool done = upload_next_band(t, image, 0, face, next_row, budget);
            after.push_back(next_row);
            EXPECT_EQ(rows_holding(image, level0(t, face)), next_row)
                << "call " << call << ", budget " << budget;
            EXPECT_EQ(done, next_row == image.height) << "call " << call;
            if (done) break;
        }
        return after;
    }
};

TEST_F(BandedUploadTest, BandsOfWholeRowsWithinTheBudgetAndAShortLastBand) {
    const Image image = numbered(5, 7, PixelFormat::RGBA8);
    gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 7);
    EXPECT_EQ(bands(t, image, 10), (std::vector<int>{2, 4, 6, 7})) << "2 rows of 5 a call, 1 in the last";
    gpu::Texture u = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 7);
    EXPECT_EQ(bands(u, image, 14), (std::vector<int>{2, 4, 6, 7})) << "a part row is left for the next call";
    gpu::Texture v = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 7);
    EXPECT_EQ(bands(v, image, 35), (std::vector<int>{7})) << "the budget is exactly the image";
}

TEST_F(BandedUploadTest, ABudgetUnderOneRowStillMovesOneRowACall) {
    const Image image = numbered(5, 3, PixelFormat::RGBA8);
    for (const long budget : {4L, 1L, 0L, -1L, LONG_MIN}) {
        gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 3);
        EXPECT_EQ(bands(t, image, budget), (std::vector<int>{1, 2, 3})) << "budget " << budget;
    }
}

TEST_F(BandedUploadTest, AHugeBudgetTakesTheRestAtOnce) {
    const Image image = numbered(5, 7, PixelFormat::RGBA8);
    gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 7);
    int next_row = 3;  // part way: the rest, not a whole image's worth past the end
    EXPECT_FALSE(upload_next_band(t, image, 0, 0, next_row, 10));  // rows 3, 4
    EXPECT_EQ(next_row, 5);
    EXPECT_TRUE(upload_next_band(t, image, 0, 0, next_row, LONG_MAX));
    EXPECT_EQ(next_row, 7);
    const std::vector<float> texels = level0(t);
    for (int y = 0; y < 7; ++y) EXPECT_EQ(row_is(image, texels, y, y >= 3), true) << "row " << y;
}

// A call with no row left (the image done, or empty) uploads nothing and says done: before the guard,
// std::clamp got a high bound under its low one (undefined) and asked GL for a row past the end.
TEST_F(BandedUploadTest, NoRowLeftIsDoneAtOnceAndUploadsNothing) {
    const Image image = numbered(5, 3, PixelFormat::RGBA8);
    gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 5, 3);
    int next_row = 3;
    EXPECT_TRUE(upload_next_band(t, image, 0, 0, next_row, 10));
    EXPECT_EQ(next_row, 3);
    EXPECT_EQ(rows_holding(image, level0(t)), 0) << "nothing was written";
    const Image empty = numbered(5, 0, PixelFormat::RGBA8);
    int row = 0;
    EXPECT_TRUE(upload_next_band(t, empty, 0, 0, row, 10));
    EXPECT_EQ(row, 0);
}

// A float texel is 16 bytes: the band's offset into the image moves by rows of bytes, not of texels.
TEST_F(BandedUploadTest, FloatImagesMoveByTheirOwnRowBytes) {
    if (!device_->caps().float_render_targets) GTEST_SKIP() << "no float render targets to read back";
    const Image image = numbered(5, 7, PixelFormat::RGBA32F);
    gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA32F, 5, 7);
    EXPECT_EQ(bands(t, image, 10), (std::vector<int>{2, 4, 6, 7}));
}

TEST_F(BandedUploadTest, ACubeFaceGetsItsRowsAndTheOtherFacesNone) {
    const Image image = numbered(4, 4, PixelFormat::RGBA8);
    gpu::Texture t = make(gpu::TextureKind::Cube, gpu::TextureFormat::RGBA8, 4, 4);
    EXPECT_EQ(bands(t, image, 12, 3), (std::vector<int>{3, 4}));
    for (int face : {0, 1, 2, 4, 5}) EXPECT_EQ(rows_holding(image, level0(t, face)), 0) << "face " << face;
}

// Level 1 of an 8x14 texture is 4x7: the image of that level goes there, level 0 keeps its clear.
TEST_F(BandedUploadTest, AMipLevelGetsItsRows) {
    const Image image = numbered(4, 7, PixelFormat::RGBA8);
    gpu::Texture t = make(gpu::TextureKind::D2, gpu::TextureFormat::RGBA8, 8, 14, 2);
    int next_row = 0;
    EXPECT_FALSE(upload_next_band(t, image, 1, 0, next_row, 16));
    EXPECT_EQ(next_row, 4);
    EXPECT_TRUE(upload_next_band(t, image, 1, 0, next_row, 16));
    EXPECT_EQ(next_row, 7);
    // test::read_texels reads a level, rows top first: image row y is read-back row 6 - y.
    const std::vector<glm::u8vec4> texels = test::read_texels(*device_, t, 1);
    ASSERT_EQ(texels.size(), 28u);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(texels[std::size_t((6 - y) * 4 + x)], glm::u8vec4(x + 1, y + 1, 7, 255))
                << x << "," << y;
    for (const glm::u8vec4 texel : test::read_texels(*device_, t, 0)) EXPECT_EQ(texel, glm::u8vec4(0));
}

}  // namespace
}  // namespace puddle::render
