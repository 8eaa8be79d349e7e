// The largest image Puddle decodes (assets/image_limits.hpp): the limits themselves pass, one pixel or
// byte past them fails with exit code 3 and a message naming the file, the size and the limit.
#include "assets/image_limits.hpp"

#include <gtest/gtest.h>

#include <string>

namespace puddle::assets {
namespace {

TEST(ImageLimits, TheLimitsThemselvesAreAllowed) {
    EXPECT_TRUE(
        check_image_size("a", max_image_side, max_image_side, PixelFormat::RGBA8).ok());  // exactly 1 GiB
    EXPECT_TRUE(check_image_size("a", 8192, 8192, PixelFormat::RGBA32F).ok());            // exactly 1 GiB
    EXPECT_FALSE(check_image_size("a", 8193, 8192, PixelFormat::RGBA32F).ok());
    EXPECT_FALSE(check_image_size("a", 1, max_image_side + 1, PixelFormat::RGBA8).ok());
    EXPECT_FALSE(check_image_size("a", 0, 1, PixelFormat::RGBA8).ok());
}

TEST(ImageLimits, EachRefusalNamesTheFileTheSizeAndTheLimit) {
    const auto empty = check_image_size("sky.png", 0, 7, PixelFormat::RGBA8);
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().code, ExitCode::Asset);
    EXPECT_EQ(empty.error().message, "image: sky.png: empty image (0x7)");
    const auto tall = check_image_size("sky.png", 4, max_image_side + 1, PixelFormat::RGBA8);
    ASSERT_FALSE(tall.ok());
    EXPECT_EQ(tall.error().code, ExitCode::Asset);
    EXPECT_EQ(tall.error().message, "image: sky.png: 4x" + std::to_string(max_image_side + 1) +
                                        " is too large: at most " + std::to_string(max_image_side) +
                                        " pixels a side");
    // 16 bytes a float pixel: 8193 x 8192 is 1 GiB and 128 KiB, reported in whole MiB.
    const auto heavy = check_image_size("sky.exr", 8193, 8192, PixelFormat::RGBA32F);
    ASSERT_FALSE(heavy.ok());
    EXPECT_EQ(heavy.error().code, ExitCode::Asset);
    EXPECT_EQ(heavy.error().message, "image: sky.exr: 8193x8192 RGBA32F needs " +
                                         std::to_string(std::size_t{8193} * 8192 * 16 >> 20) +
                                         " MiB decoded, more than the " +
                                         std::to_string(max_image_bytes >> 20) + " MiB limit");
}

}  // namespace
}  // namespace puddle::assets
