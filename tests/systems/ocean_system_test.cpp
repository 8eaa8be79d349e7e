// The ocean scene (systems/ocean/ocean_system.hpp, REFERENCE.md section 2): each parameter moves the sea the
// way its name says, and the camera puts the horizon where a pinhole camera would.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "systems/ocean/ocean_height_map.hpp"
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

// The reference's camera, looking down at the sea: all of the picture is water.
const std::string down_from = "ocean.camera_position=0,5,5", down_at = "ocean.camera_target=0,0,0";

TEST(OceanScene, MoreChoppinessGivesRougherWater) {
    const auto smooth = render_with({"scene.kind=ocean", down_from, down_at, "ocean.choppiness=1"}, 2);
    const auto choppy = render_with({"scene.kind=ocean", down_from, down_at, "ocean.choppiness=8"}, 2);
    EXPECT_GT(roughness(choppy), 1.3 * roughness(smooth)) << roughness(choppy) << " vs " << roughness(smooth);
}

TEST(OceanScene, SeaColourColoursTheWater) {
    const auto green =
        render_with({"scene.kind=ocean", down_from, down_at, "ocean.sea_color=0.05,0.4,0.05"}, 2);
    const auto red =
        render_with({"scene.kind=ocean", down_from, down_at, "ocean.sea_color=0.4,0.05,0.05"}, 2);
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

// Mean |luma difference| between horizontal neighbours along row y: the sky (its gradient, the sun's
// glow) hardly changes from pixel to pixel.
double row_roughness(const assets::Image& img, int y) {
    double sum = 0;
    for (int x = 0; x + 1 < img.width; ++x) {
        const std::uint8_t *a = img.pixel8(x, y), *b = img.pixel8(x + 1, y);
        sum += std::abs((0.299 * a[0] + 0.587 * a[1] + 0.114 * a[2]) -
                        (0.299 * b[0] + 0.587 * b[1] + 0.114 * b[2]));
    }
    return sum / (img.width - 1);
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
                                     2, {320, 180});
        ASSERT_EQ(img.height, 180);
        const double tan_pitch = (target_y - 4) / 15.0;
        const double horizon = img.height / 2.0 * (1 + tan_pitch / tan_half_fov);  // rows from the top
        // The horizon: where the bright haze meets the darker sea, the largest drop in brightness between
        // rows.
        int edge = 1;
        double largest_drop = 0;
        for (int y = 1; y < img.height; ++y) {
            const double drop =
                mean_luma(img, 0, y - 1, img.width, y) - mean_luma(img, 0, y, img.width, y + 1);
            if (drop > largest_drop) largest_drop = drop, edge = y;
        }
        // The sea ends where the march does, ocean_far away: 4 / 400 radians below the horizon.
        EXPECT_NEAR(edge, horizon + img.height / 2.0 * (4.0 / systems::ocean_far) / tan_half_fov, 1.5);
        const int h = static_cast<int>(horizon);
        EXPECT_GT(mean_luma(img, 0, 0, img.width, h - 2),
                  mean_luma(img, 0, h + 2, img.width, img.height) + 40);
        for (int y = 0; y < h - 2; ++y)
            EXPECT_LT(row_roughness(img, y), 1.0) << "the sky is smooth, row " << y;
    }
}

// ocean.method: the height map (the default) and the secant search (its fallback), each a fixed, small
// cost, give the reference march's picture. Stated tolerance, in levels of 255, per method and view (the
// default, to the horizon, and the reference's camera looking down): the secant search at most a mean of
// 2 and 2% of the pixels off by more than 24 looking down, 4 and 6% toward the horizon, the pixels off
// lying along the horizon and the crests' silhouettes, where the four-octave search meets a grazing wave a
// little before or after the reference's full-height march (which itself steps up to 2 units). The height
// map's normals are the map's, over a texel of two pixels, and it holds only the octaves a texel can: the
// crests' thin creases are softer, and the far water, which the reference samples one point a pixel, is
// smoother, its colour from the slopes the map could not hold: at most a mean of 2 and 2% looking down, 6
// and 10% toward the horizon. At 640x360: the map follows the screen, and at 160 wide a texel is a large
// piece of sea.
TEST(OceanScene, TheFixedCostMethodsGiveTheReferenceMarchsPicture) {
    struct View {
        std::string method, position, target;
        double mean, fraction;
    };
    const glm::ivec2 size{640, 360};  // the map's texel is two pixels: at 160 wide, a large piece of sea
    const std::string to_horizon[2] = {"ocean.camera_position=0,4,5", "ocean.camera_target=0,3,-10"};
    const std::string down[2] = {"ocean.camera_position=0,5,5", "ocean.camera_target=0,0,0"};
    for (const View& v : {View{"secant", down[0], down[1], 2.0, 0.02},
                          View{"secant", to_horizon[0], to_horizon[1], 4.0, 0.06},
                          View{"height_map", down[0], down[1], 2.0, 0.02},
                          View{"height_map", to_horizon[0], to_horizon[1], 6.0, 0.10}}) {
        SCOPED_TRACE(v.method + " " + v.position);
        const auto fixed = render_with(
            {"scene.kind=ocean", "overlay.rain=false", "ocean.method=" + v.method, v.position, v.target}, 2,
            size);
        const auto reference = render_with(
            {"scene.kind=ocean", "overlay.rain=false", "ocean.method=reference", v.position, v.target}, 2,
            size);
        ASSERT_EQ(fixed.width, reference.width);
        const ImageDiff d = compare_images(fixed, reference, 24);
        EXPECT_LT(d.mean_abs_diff, v.mean);
        EXPECT_LT(d.fraction_over, v.fraction);
        std::printf("%s %s: mean %.2f, %.3f over 24\n", v.method.c_str(), v.position.c_str(), d.mean_abs_diff,
                    d.fraction_over);
        const auto other_sea =
            render_with({"scene.kind=ocean", "overlay.rain=false", "ocean.method=" + v.method, v.position,
                         v.target, "ocean.height=0.2"},
                        2, size);
        EXPECT_GT(compare_images(fixed, other_sea, 24).fraction_over, 3 * v.fraction)
            << "the comparison tells another sea apart";
    }
}

// A clear day at sea: the ocean takes no rain streaks (Looks' takes_rain_overlay), whatever overlay.rain
// says.
TEST(OceanScene, TakesNoRainStreaks) {
    const auto with = render_with({"scene.kind=ocean", "overlay.rain=true", "overlay.rain_opacity=1"}, 4);
    const auto without = render_with({"scene.kind=ocean", "overlay.rain=false"}, 4);
    ASSERT_FALSE(with.empty() || without.empty());
    EXPECT_EQ(compare_images(with, without, 0).max_channel_diff, 0);
}

// Where the map cannot be made the ocean is the secant search's, exactly: an eye among the crests (the
// plane of the highest crest seen edge on), and a GPU without half-float render targets.
TEST(OceanScene, WithoutItsHeightMapTheOceanIsTheSecantSearchs) {
    struct Case {
        const char* what;
        std::vector<std::string> sets;
        bool no_float_targets;
    };
    for (const Case& c : {Case{"an eye among the crests",
                               {"ocean.camera_position=0,1.5,5", "ocean.camera_target=0,1,-10"},
                               false},
                          Case{"no half-float targets", {}, true}}) {
        SCOPED_TRACE(c.what);
        auto render = [&](const char* method) {
            params::Params p = make_params(
                {"wave.resolution=256", "rain.seed=11", "scene.kind=ocean", "overlay.rain=false", method});
            apply_sets(p, c.sets);
            auto engine = make_engine(p, render_test_size, {.forbid_float_targets = c.no_float_targets});
            return engine ? render_frames(*engine, 2) : assets::Image{};
        };
        const auto map = render("ocean.method=height_map"), secant = render("ocean.method=secant");
        ASSERT_FALSE(map.empty() || secant.empty());
        EXPECT_EQ(compare_images(map, secant, 0).max_channel_diff, 0);
    }
    // And where it can, the two differ (the comparison above can fail).
    const auto map = render_with({"scene.kind=ocean", "overlay.rain=false"}, 2);
    const auto secant = render_with({"scene.kind=ocean", "overlay.rain=false", "ocean.method=secant"}, 2);
    EXPECT_GT(compare_images(map, secant, 0).max_channel_diff, 0);
}

}  // namespace
}  // namespace puddle::test
