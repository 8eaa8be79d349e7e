// The ocean scene (systems/ocean/ocean_system.hpp, REFERENCE.md section 2): each parameter moves the sea the
// way its name says, and the camera puts the horizon where a pinhole camera would.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

// Mean |luma difference| between horizontal and vertical neighbours: how busy (rough) the picture is.
double roughness(const assets::Image& img) {
    auto luma = [&](int x, int y) {
        const std::uint8_t* p = &img.data[(static_cast<std::size_t>(y) * img.width + x) * 4];
        return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    };
    double sum = 0;
    int n = 0;
    for (int y = 0; y + 1 < img.height; ++y)
        for (int x = 0; x + 1 < img.width; ++x, ++n)
            sum += std::abs(luma(x + 1, y) - luma(x, y)) + std::abs(luma(x, y + 1) - luma(x, y));
    return sum / n;
}

TEST(OceanScene, MoreChoppinessGivesRougherWater) {
    const auto smooth = render_with({"scene.kind=ocean", "ocean.choppiness=1"}, 2);
    const auto choppy = render_with({"scene.kind=ocean", "ocean.choppiness=8"}, 2);
    EXPECT_GT(roughness(choppy), 1.3 * roughness(smooth)) << roughness(choppy) << " vs " << roughness(smooth);
}

TEST(OceanScene, SeaColourColoursTheWater) {
    const auto green = render_with({"scene.kind=ocean", "ocean.sea_color=0.05,0.4,0.05"}, 2);
    const auto red = render_with({"scene.kind=ocean", "ocean.sea_color=0.4,0.05,0.05"}, 2);
    auto mean = [](const assets::Image& img, int c) {
        double s = 0;
        for (std::size_t i = static_cast<std::size_t>(c); i < img.data.size(); i += 4) s += img.data[i];
        return s / (static_cast<double>(img.data.size()) / 4);
    };
    EXPECT_GT(mean(green, 1) - mean(red, 1), 20);
    EXPECT_GT(mean(red, 0) - mean(green, 0), 20);
}

TEST(OceanScene, WavesMoveWithTime) {
    // Without the falling rain, which moves whatever the sea does.
    const auto early = render_with({"scene.kind=ocean", "overlay.rain=false"}, 2);
    const auto later = render_with({"scene.kind=ocean", "overlay.rain=false"}, 30);
    const auto slow_later = render_with({"scene.kind=ocean", "ocean.speed=0", "overlay.rain=false"}, 30);
    const auto slow_early = render_with({"scene.kind=ocean", "ocean.speed=0", "overlay.rain=false"}, 2);
    EXPECT_GT(compare_images(early, later, 8).fraction_over, 0.05);
    EXPECT_EQ(compare_images(slow_early, slow_later, 0).max_channel_diff, 0) << "speed 0 stops the sea";
}

// Looking out to sea from (0, 4, 5) toward (0, target_y, -10): the horizon (elevation 0) shows at
// tan(pitch) / tan(fov / 2) of the half height below the centre when the camera looks up, above it when
// down (a pinhole camera without roll). Above it the sky is smooth (no streaks fall in front of it) and
// brighter than the sea.
TEST(OceanScene, TheHorizonIsWhereTheCameraPutsIt) {
    const double tan_half_fov = std::tan(60.0 / 2 * 3.14159265358979 / 180);  // camera.fov's default
    for (const int target_y : {2, 4, 6}) {
        SCOPED_TRACE(target_y);
        const auto img = render_with({"scene.kind=ocean", "overlay.rain=false", "ocean.camera_position=0,4,5",
                                      "ocean.camera_target=0," + std::to_string(target_y) + ",-10"},
                                     2);
        ASSERT_EQ(img.height, render_test_size.y);
        const double tan_pitch = (target_y - 4) / 15.0;
        const double horizon = img.height / 2.0 * (1 + tan_pitch / tan_half_fov);  // rows from the top
        EXPECT_NEAR(first_rough_row(img, 10.0), horizon, 1.5);
        const int h = static_cast<int>(horizon);
        EXPECT_GT(mean_luma(img, 0, 0, img.width, h - 2),
                  mean_luma(img, 0, h + 2, img.width, img.height) + 60);
        EXPECT_LT(row_contrast(img, 0, h - 2), 3.0) << "the sky is smooth";
    }
}

// ocean.method: the default secant search (a fixed, small cost) gives the reference march's picture.
// Stated tolerance, in levels of 255: looking down on the sea (the default camera) a mean of at most 2 and
// at most 2% of the pixels off by more than 24; toward the horizon a mean of at most 4 and 6%, the pixels
// off lying along the horizon and the crests' silhouettes, where the four-octave search meets a grazing
// wave a little before or after the reference's full-height march (which itself steps up to 2 units).
TEST(OceanScene, TheSecantSearchGivesTheReferenceMarchsPicture) {
    struct View {
        std::string position, target;
        double mean, fraction;
    };
    for (const View& v : {View{"ocean.camera_position=0,5,5", "ocean.camera_target=0,0,0", 2.0, 0.02},
                          View{"ocean.camera_position=0,4,5", "ocean.camera_target=0,3,-10", 4.0, 0.06}}) {
        SCOPED_TRACE(v.position);
        const auto secant = render_with({"scene.kind=ocean", "overlay.rain=false", v.position, v.target}, 2);
        const auto reference = render_with(
            {"scene.kind=ocean", "overlay.rain=false", "ocean.method=reference", v.position, v.target}, 2);
        ASSERT_EQ(secant.width, reference.width);
        const ImageDiff d = compare_images(secant, reference, 24);
        EXPECT_LT(d.mean_abs_diff, v.mean);
        EXPECT_LT(d.fraction_over, v.fraction);
        const auto other_sea = render_with(
            {"scene.kind=ocean", "overlay.rain=false", v.position, v.target, "ocean.height=0.2"}, 2);
        EXPECT_GT(compare_images(secant, other_sea, 24).fraction_over, 3 * v.fraction)
            << "the comparison tells another sea apart";
    }
}

}  // namespace
}  // namespace puddle::test
