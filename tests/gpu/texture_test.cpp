// The mip chain's length, shared by every texture that has one (sky cube, panorama, camera textures).
#include "gpu/texture.hpp"

#include <gtest/gtest.h>

namespace puddle::gpu {
namespace {

TEST(FullMipCount, IsFloorLog2PlusOneDownToOneTexel) {
    EXPECT_EQ(full_mip_count(1), 1);
    EXPECT_EQ(full_mip_count(2), 2);
    EXPECT_EQ(full_mip_count(3), 2);
    EXPECT_EQ(full_mip_count(256), 9);
    EXPECT_EQ(full_mip_count(255), 8);
    EXPECT_EQ(full_mip_count(4096), 13);
    EXPECT_EQ(full_mip_count(8192 + 1), 14);
    EXPECT_EQ(full_mip_count(0), 1);
    EXPECT_EQ(full_mip_count(-5), 1);
}

}  // namespace
}  // namespace puddle::gpu
