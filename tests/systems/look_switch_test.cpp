// A look chosen while the display runs is built off the frame thread (systems/common/look_switch.hpp,
// gpu/pipeline_compiler.hpp): frames go on showing the old look while the worker has not built the new
// one, and the first frame after it is ready shows the new look exactly as an engine started with it.
#include "systems/common/look_switch.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "params/config_loader.hpp"
#include "support/gated_worker_context.hpp"
#include "support/test_support.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/shown_look.hpp"
#include "systems/ocean/ocean_system.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

void set(app::Engine& e, const std::string& assignment) {
    auto a = params::parse_assignment(assignment);
    ASSERT_TRUE(a.ok()) << assignment;
    e.params().set(a->id, a->value, params::ParamSource::CommandLine);
}

// Runs frames until the engine shows `scene` (at most 20 s of waiting for the worker); the frame count.
int frames_until_shown(app::Engine& engine, systems::Scene scene) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int frames = 0;
    while (engine.world().resource<systems::ShownLook>().scene != scene &&
           std::chrono::steady_clock::now() < give_up) {
        EXPECT_TRUE(engine.frame(1.0 / 60.0).ok());
        ++frames;
    }
    return frames;
}

TEST(LookSwitch, ANewSceneIsBuiltOffTheFrameThreadAndShownWhenReady) {
    auto engine = make_engine(make_params({"wave.resolution=256", "rain.seed=11"}), render_test_size);
    ASSERT_TRUE(engine);
    auto context = engine->display().create_worker_context();
    ASSERT_TRUE(context.ok()) << context.error().message;
    auto gated = std::make_unique<GatedContext>(std::move(context).value());
    GatedContext& gate = *gated;
    engine->device().start_background_compiles(std::move(gated));

    const auto before = render_frames(*engine, 5);
    set(*engine, "scene.kind=ocean");
    // The worker is held: frames go on, showing the puddle. With the compile on the frame thread the first
    // of these frames would have waited for it and shown the ocean.
    const auto while_building = render_frames(*engine, 3);
    EXPECT_EQ(engine->world().resource<systems::ShownLook>().scene, systems::Scene::puddle);
    EXPECT_LT(compare_images(before, while_building, 32).fraction_over, 0.2) << "still the puddle";

    gate.open();
    const int more = frames_until_shown(*engine, systems::Scene::ocean);
    ASSERT_EQ(engine->world().resource<systems::ShownLook>().scene, systems::Scene::ocean);
    const auto ocean = render_frames(*engine, 1);  // frame 5 + 3 + more + 1
    // The ocean is a function of time: an engine started with it, at the same frame, draws the same.
    const auto ocean_fresh = render_with({"scene.kind=ocean"}, 5 + 3 + more + 1);
    EXPECT_LT(compare_images(ocean, ocean_fresh, 8).fraction_over, 0.001);
    EXPECT_GT(compare_images(while_building, ocean, 8).fraction_over, 0.5);
}

TEST(LookSwitch, ALookThatFailsToBuildIsNeverShown) {
    auto engine = make_engine(make_params({"wave.resolution=256", "rain.seed=11"}), render_test_size);
    ASSERT_TRUE(engine);
    auto context = engine->display().create_worker_context();
    ASSERT_TRUE(context.ok()) << context.error().message;
    engine->device().start_background_compiles(std::move(context).value());
    // As if ocean.frag had not compiled on this GPU: the pipeline is marked failed.
    auto& ocean = engine->world().resource<systems::OceanRenderer>();
    for (systems::FullscreenPass* pass : {&ocean.mapped, &ocean.secant})
        pass->cache.fail({}, {"test: ocean.frag does not compile here"});
    const auto before = render_frames(*engine, 3);
    set(*engine, "scene.kind=ocean");
    const auto after = render_frames(*engine, 10);
    EXPECT_EQ(engine->world().resource<systems::ShownLook>().scene, systems::Scene::puddle);
    EXPECT_LT(compare_images(before, after, 32).fraction_over, 0.2) << "the puddle stays, not a black frame";
}

// The switch knows no look by name: it asks the chosen look's entry in Looks, every frame until the
// entry is ready, and moves ShownLook then; a look with no entry (the puddle's pulse drops) is shown at once.
TEST(LookSwitch, TheChosenLooksEntryIsAskedUntilItIsReady) {
    auto engine = make_engine(make_params({"wave.resolution=64"}), render_test_size);
    ASSERT_TRUE(engine);
    int asked = 0, prepared = 0;
    systems::Looks looks;
    looks.entries.push_back({.scene = systems::Scene::street,
                             .prepare = [&](gpu::Device&) { return ++prepared, Result<void>{}; },
                             .request = [&](gpu::Device&) { return ++asked >= 3; }});
    systems::ShownLook shown;
    params::Params& params = engine->params();
    params.set(params::ParamId::scene_kind, std::string("street"), params::ParamSource::CommandLine);
    systems::look_switch_system(engine->device(), params, looks, shown);
    systems::look_switch_system(engine->device(), params, looks, shown);
    EXPECT_EQ(shown.scene, systems::Scene::puddle) << "not ready after two asks";
    systems::look_switch_system(engine->device(), params, looks, shown);
    EXPECT_EQ(shown.scene, systems::Scene::street);
    systems::look_switch_system(engine->device(), params, looks, shown);
    EXPECT_EQ(asked, 3) << "a shown look is not asked again";
    EXPECT_EQ(prepared, 0) << "the switch builds off the frame thread, never with prepare";
    ASSERT_TRUE(systems::prepare_chosen_look(engine->device(), looks, shown).ok());
    EXPECT_EQ(prepared, 1);

    params.set(params::ParamId::scene_kind, std::string("puddle"), params::ParamSource::CommandLine);
    systems::look_switch_system(engine->device(), params, looks, shown);
    EXPECT_EQ(shown.scene, systems::Scene::puddle) << "no entry: nothing to build";
    EXPECT_EQ(asked, 3);
}

}  // namespace
}  // namespace puddle::test
