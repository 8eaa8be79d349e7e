// Scenes and the rain overlay chosen by config (REFERENCE.md sections 2 and 3): each parameter moves the
// picture the way its name says, and a scene switched between frames shows on the next frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "params/config_loader.hpp"
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

void set(app::Engine& e, const std::string& assignment) {
    auto a = params::parse_assignment(assignment);
    ASSERT_TRUE(a.ok()) << assignment;
    e.params().set(a->id, a->value, params::ParamSource::CommandLine);
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
    const auto early = render_with({"scene.kind=ocean"}, 2);
    const auto later = render_with({"scene.kind=ocean"}, 30);
    const auto slow_later = render_with({"scene.kind=ocean", "ocean.speed=0"}, 30);
    const auto slow_early = render_with({"scene.kind=ocean", "ocean.speed=0"}, 2);
    EXPECT_GT(compare_images(early, later, 8).fraction_over, 0.05);
    EXPECT_EQ(compare_images(slow_early, slow_later, 0).max_channel_diff, 0) << "speed 0 stops the sea";
}

// Mean over rows [y0, y1) of each row's luma standard deviation: the sky is smooth along a row, the
// ground (puddles) and the sea (waves) are not.
double row_contrast(const assets::Image& img, int y0, int y1) {
    double sum = 0;
    for (int y = y0; y < y1; ++y) sum += luma_stddev(img, 0, y, img.width, y + 1);
    return sum / (y1 - y0);
}

// The first row from the top whose contrast along it passes `threshold`: where the smooth sky ends.
int first_rough_row(const assets::Image& img, double threshold) {
    for (int y = 0; y < img.height; ++y)
        if (luma_stddev(img, 0, y, img.width, y + 1) > threshold) return y;
    return img.height;
}

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

// Looking out to sea from (0, 4, 5) toward (0, target_y, -10): the horizon (elevation 0) shows at
// tan(pitch) / tan(fov / 2) of the half height below the centre when the camera looks up, above it when
// down (a pinhole camera without roll). Above it the sky is smooth and brighter than the sea.
TEST(OceanScene, TheHorizonIsWhereTheCameraPutsIt) {
    const double tan_half_fov = std::tan(60.0 / 2 * 3.14159265358979 / 180);  // camera.fov's default
    for (const int target_y : {2, 4, 6}) {
        SCOPED_TRACE(target_y);
        const auto img = render_with({"scene.kind=ocean", "ocean.camera_position=0,4,5",
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

TEST(StreetScene, RipplesBrightenThePuddles) {
    const auto none = render_with({"scene.kind=street", "street.ripples=0", "street.splashes=0"}, 40);
    const auto many = render_with({"scene.kind=street", "street.ripples=32", "street.splashes=0"}, 40);
    // Only below the horizon (rows from 58% of the height down).
    EXPECT_GT(mean_luma(many, 0, 53, 160, 90), mean_luma(none, 0, 53, 160, 90) + 0.2);
    EXPECT_GT(compare_images(none, many, 8).fraction_over, 0.002);
}

// Pixels the overlay changed (by more than 8 of 255 in any channel) against the same frame without it.
double streak_fraction(std::initializer_list<std::string> overlay_sets) {
    const auto plain = render_with({"scene.kind=street"}, 10);
    std::vector<std::string> sets{"scene.kind=street", "overlay.rain=true"};
    sets.insert(sets.end(), overlay_sets);
    params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
    apply_sets(p, sets);
    auto engine = make_engine(p, render_test_size);
    if (!engine) return -1;
    return compare_images(plain, render_frames(*engine, 10), 8).fraction_over;
}

TEST(RainOverlay, MoreDensityGivesMoreStreakPixels) {
    const double sparse = streak_fraction({"overlay.rain_density=0.4"});
    const double dense = streak_fraction({"overlay.rain_density=2"});
    EXPECT_GT(sparse, 0.005);
    EXPECT_GT(dense, 1.5 * sparse) << dense << " vs " << sparse;
}

TEST(RainOverlay, OffOrTransparentChangesNothing) {
    EXPECT_EQ(streak_fraction({"overlay.rain_opacity=0"}), 0.0);
    EXPECT_EQ(streak_fraction({"overlay.rain_density=0"}), 0.0);
}

TEST(RainOverlay, StreaksTakeTheRainColour) {
    const auto plain = render_with({"scene.kind=ocean"}, 2);
    const auto red = render_with({"scene.kind=ocean", "overlay.rain=true", "overlay.rain_color=1,0,0",
                                  "overlay.rain_opacity=1", "overlay.rain_density=2"},
                                 2);
    int redder = 0, bluer = 0;
    for (std::size_t i = 0; i < red.data.size(); i += 4) {
        const int dr = red.data[i] - plain.data[i], db = red.data[i + 2] - plain.data[i + 2];
        if (dr > 8) ++redder;
        if (db > 8) ++bluer;
    }
    EXPECT_GT(redder, 50);
    EXPECT_EQ(bluer, 0);
}

// Live tuning changes parameters between frames: the next frame must show the new scene, the same as an
// engine started with it (the ocean and street are functions of time; both engines are at the same time).
TEST(SceneSwitch, ChangingSceneBetweenFramesShowsTheNewScene) {
    auto engine = make_engine(make_params({"wave.resolution=256", "rain.seed=11"}), render_test_size);
    ASSERT_TRUE(engine);
    const auto puddle = render_frames(*engine, 5);
    set(*engine, "scene.kind=ocean");
    const auto ocean = render_frames(*engine, 1);
    set(*engine, "scene.kind=street");
    const auto street = render_frames(*engine, 1);
    set(*engine, "scene.kind=puddle");
    const auto puddle_again = render_frames(*engine, 1);

    const auto ocean_fresh = render_with({"scene.kind=ocean"}, 6);
    const auto street_fresh = render_with({"scene.kind=street"}, 7);
    EXPECT_LT(compare_images(ocean, ocean_fresh, 8).fraction_over, 0.001);
    EXPECT_LT(compare_images(street, street_fresh, 8).fraction_over, 0.001);
    EXPECT_GT(compare_images(puddle, ocean, 8).fraction_over, 0.5);
    EXPECT_GT(compare_images(ocean, street, 8).fraction_over, 0.5);
    EXPECT_LT(compare_images(puddle, puddle_again, 32).fraction_over, 0.2) << "the puddle is back";
}

TEST(SceneSwitch, ChangingDropModelBetweenFramesSwitchesTheRipples) {
    // The references first: each engine owns an EGL context, and one at a time keeps the test simple.
    const auto grid_fresh = render_with({"drops.model=grid"}, 6);
    const auto analytic_fresh = render_with({"drops.model=analytic"}, 7);
    auto engine = make_engine(make_params({"wave.resolution=256", "rain.seed=11"}), render_test_size);
    ASSERT_TRUE(engine);
    render_frames(*engine, 5);
    set(*engine, "drops.model=grid");
    const auto grid = render_frames(*engine, 1);
    set(*engine, "drops.model=analytic");
    const auto analytic = render_frames(*engine, 1);
    EXPECT_LT(compare_images(grid, grid_fresh, 8).fraction_over, 0.001);
    EXPECT_LT(compare_images(analytic, analytic_fresh, 8).fraction_over, 0.001);
    EXPECT_GT(compare_images(grid, analytic, 8).fraction_over, 0.01);
}

}  // namespace
}  // namespace puddle::test
