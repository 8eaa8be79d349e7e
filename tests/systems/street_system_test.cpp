// The rainy street (systems/street/street_system.hpp, REFERENCE.md section 3): the horizon splits a smooth
// sky from the puddled ground where street.horizon puts it, and ripples brighten the puddles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

// street.horizon is the horizon's height above the bottom of the screen: above it a smooth sky, below it
// the ground's puddles. Fails if the horizon ignored the parameter or were measured from the top.
TEST(StreetScene, HorizonSplitsSkyFromGround) {
    for (const float horizon : {0.3f, 0.7f}) {
        SCOPED_TRACE(horizon);
        const auto img = render_with({"scene.kind=street", "street.horizon=" + std::to_string(horizon)}, 2);
        ASSERT_EQ(img.height, render_test_size.y);
        const int row = static_cast<int>(std::lround(img.height * (1.0 - horizon)));  // from the top
        const double sky = row_contrast(img, 0, row - 4), ground = row_contrast(img, row + 4, img.height);
        EXPECT_GT(ground, 2.5 * sky) << "ground " << ground << ", sky " << sky;
        // Fog thins the ground's contrast just below the horizon, so the puddles show a few rows lower.
        const int rough = first_rough_row(img, 8.0);
        EXPECT_GE(rough, row - 2);
        EXPECT_LE(rough, row + 6);
    }
}

TEST(StreetScene, RipplesBrightenThePuddles) {
    const auto none = render_with({"scene.kind=street", "street.ripples=0", "street.splashes=0"}, 40);
    const auto many = render_with({"scene.kind=street", "street.ripples=32", "street.splashes=0"}, 40);
    // Only below the horizon (rows from 58% of the height down).
    EXPECT_GT(mean_luma(many, 0, 53, 160, 90), mean_luma(none, 0, 53, 160, 90) + 0.2);
    EXPECT_GT(compare_images(none, many, 8).fraction_over, 0.002);
}

}  // namespace
}  // namespace puddle::test
