// Plane geometry of uncompressed camera frames: chroma of odd sizes rounded up, strides honoured,
// impossible strides refused.
#include "camera/frame_layout.hpp"

#include <gtest/gtest.h>

namespace puddle::test {
namespace {

using camera::frame_layout;
using camera::PixelLayout;

TEST(FrameLayout, Nv12ChromaCoversTheLastColumnAndRowOfAnOddSize) {
    // 65x49, bytesperline 80: the chroma plane has ceil(65/2) = 33 pairs a row and ceil(49/2) = 25 rows.
    auto f = frame_layout(PixelLayout::Nv12, 65, 49, 80);
    ASSERT_TRUE(f) << f.error().message;
    ASSERT_EQ(f->count, 2);
    EXPECT_EQ(f->planes[0].texels, 65);
    EXPECT_EQ(f->planes[0].rows, 49);
    EXPECT_EQ(f->planes[1].offset, 80u * 49) << "the chroma plane follows every luma row";
    EXPECT_EQ(f->planes[1].stride, 80);
    EXPECT_EQ(f->planes[1].texels, 33);
    EXPECT_EQ(f->planes[1].row_bytes, 66);
    EXPECT_EQ(f->planes[1].rows, 25);
    EXPECT_EQ(f->bytes, 80u * 49 + 80u * 24 + 66) << "the last chroma row may omit its padding";
    // The shared case's size: even height, odd width.
    auto g = frame_layout(PixelLayout::Nv12, 65, 48, 80);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->planes[1].texels, 33);
    EXPECT_EQ(g->planes[1].rows, 24);
}

TEST(FrameLayout, YuyvOfAnOddWidthEndsInAWholePair) {
    auto f = frame_layout(PixelLayout::Yuyv, 5, 3, 24);
    ASSERT_TRUE(f) << f.error().message;
    ASSERT_EQ(f->count, 1);
    EXPECT_EQ(f->planes[0].texels, 3);
    EXPECT_EQ(f->planes[0].row_bytes, 12);
    EXPECT_EQ(f->bytes, 24u * 2 + 12);
}

TEST(FrameLayout, AStrideShorterThanARowIsRefused) {
    auto chroma = frame_layout(PixelLayout::Nv12, 65, 48, 65);
    ASSERT_FALSE(chroma);
    EXPECT_EQ(chroma.error().message,
              "NV12 65x48: bytesperline 65 is shorter than the 66 bytes of a chroma row");
    auto pixels = frame_layout(PixelLayout::Yuyv, 64, 48, 100);
    ASSERT_FALSE(pixels);
    EXPECT_EQ(pixels.error().message,
              "YUYV 64x48: bytesperline 100 is shorter than the 128 bytes of a pixel row");
    auto empty = frame_layout(PixelLayout::Nv12, 0, 48, 64);
    ASSERT_FALSE(empty);
    EXPECT_EQ(empty.error().message, "NV12 0x48: each side must be 1 to 16384 pixels");
}

}  // namespace
}  // namespace puddle::test
