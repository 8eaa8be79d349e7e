// Choosing the look (systems/scene_select.hpp): a scene or drop model changed between frames shows on the
// next frame, the same as an engine started with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

void set(app::Engine& e, const std::string& assignment) {
    auto a = params::parse_assignment(assignment);
    ASSERT_TRUE(a.ok()) << assignment;
    e.params().set(a->id, a->value, params::ParamSource::CommandLine);
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
