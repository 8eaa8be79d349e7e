// Choosing the look (systems/common/shown_look.hpp): a scene or drop model changed between frames shows on
// the next frame, the same as an engine started with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/test_support.hpp"
#include "systems/common/shown_look.hpp"
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

namespace puddle::systems {
namespace {

// The run conditions read the look on screen (ShownLook) and Params, each by its name in describe().
TEST(RunConditions, ReadTheLookOnScreenAndTheOverlaySwitch) {
    ecs::World world;
    auto& shown = world.insert_resource<ShownLook>();
    auto& params = world.insert_resource<params::Params>();
    const auto ocean = look_is(Scene::ocean), grid = drops_are(DropModel::grid), field = wave_field_in_use(),
               overlay = rain_overlay_on();
    EXPECT_EQ(ocean.name, "look is ocean");
    EXPECT_EQ(grid.name, "drops are grid");
    EXPECT_EQ(field.name, "the wave field is in use");
    EXPECT_EQ(overlay.name, "the rain overlay is on");
    EXPECT_FALSE(ocean.test(world));
    EXPECT_TRUE(field.test(world)) << "the puddle with pulse drops";
    shown.drops = DropModel::grid;
    EXPECT_TRUE(grid.test(world));
    EXPECT_FALSE(field.test(world));
    shown.scene = Scene::ocean;
    EXPECT_TRUE(ocean.test(world));
    EXPECT_FALSE(grid.test(world)) << "drops belong to the puddle only";
    EXPECT_TRUE(overlay.test(world)) << "falling rain is on by default";
    params.set<params::ParamId::overlay_rain>(false, params::ParamSource::CommandLine);
    EXPECT_FALSE(overlay.test(world));
}

// The wave field runs for the puddle's pulse drops only: another scene needs none, whatever drops.model
// says; each scene's condition holds for that scene alone.
TEST(RunConditions, TheWaveFieldAndEachSceneByTheLookOnScreen) {
    ecs::World world;
    auto& shown = world.insert_resource<ShownLook>();
    const auto field = wave_field_in_use(), analytic = drops_are(DropModel::analytic);
    for (const Scene scene : {Scene::puddle, Scene::ocean, Scene::street}) {
        shown = {.scene = scene, .drops = DropModel::pulse};
        EXPECT_EQ(field.test(world), scene == Scene::puddle) << params::choice_name(scene);
        for (const Scene other : {Scene::puddle, Scene::ocean, Scene::street})
            EXPECT_EQ(look_is(other).test(world), other == scene)
                << params::choice_name(other) << " on " << params::choice_name(scene);
    }
    shown = {.scene = Scene::puddle, .drops = DropModel::analytic};
    EXPECT_TRUE(analytic.test(world));
    EXPECT_FALSE(field.test(world));
    EXPECT_EQ(look_is(Scene::puddle).name, "look is puddle");
    EXPECT_EQ(drops_are(DropModel::pulse).name, "drops are pulse");
}

// The look the parameters choose (scene.kind, drops.model), and its name in the log.
TEST(SceneSelect, TheSelectedLookIsWhatTheParametersSay) {
    params::Params params;
    params.set<params::ParamId::scene_kind>(Scene::street, params::ParamSource::CommandLine);
    params.set<params::ParamId::drops_model>(DropModel::grid, params::ParamSource::CommandLine);
    EXPECT_EQ(selected_scene(params), Scene::street);
    EXPECT_EQ(selected_drop_model(params), DropModel::grid);
    EXPECT_EQ(selected_look(params), (ShownLook{.scene = Scene::street, .drops = DropModel::grid}));
    params.set<params::ParamId::scene_kind>(Scene::puddle, params::ParamSource::CommandLine);
    params.set<params::ParamId::drops_model>(DropModel::analytic, params::ParamSource::CommandLine);
    EXPECT_EQ(selected_look(params), (ShownLook{.scene = Scene::puddle, .drops = DropModel::analytic}));
}

TEST(SceneSelect, DescribeNamesTheSceneAndThePuddlesDrops) {
    EXPECT_EQ(describe({.scene = Scene::puddle, .drops = DropModel::pulse}), "puddle with pulse drops");
    EXPECT_EQ(describe({.scene = Scene::puddle, .drops = DropModel::analytic}), "puddle with analytic drops");
    EXPECT_EQ(describe({.scene = Scene::puddle, .drops = DropModel::grid}), "puddle with grid drops");
    for (const DropModel drops : {DropModel::pulse, DropModel::analytic, DropModel::grid}) {
        EXPECT_EQ(describe({.scene = Scene::ocean, .drops = drops}), "ocean")
            << "drops are the puddle's only";
        EXPECT_EQ(describe({.scene = Scene::street, .drops = drops}), "street");
    }
}

}  // namespace
}  // namespace puddle::systems
