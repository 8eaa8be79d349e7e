// Tests for systems/puddle/puddle_plugin.hpp: the plugin alone in a world (a Device, Params and RenderTarget,
// as its header asks, and nothing of the engine's) registers its systems with their stages and run conditions
// in the order written there, builds the resources its systems read, and stops with the asset's error when
// the sky does not load.
#include "systems/puddle/puddle_plugin.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "support/gpu_fixture.hpp"
#include "support/puddle_schedule.hpp"
#include "systems/common/shown_look.hpp"
#include "systems/puddle/render_system.hpp"
#include "systems/water/surface_system.hpp"
#include "systems/water/wave_system.hpp"

namespace puddle::systems {
namespace {

class PuddlePluginTest : public ::testing::Test {
protected:
    void SetUp() override {
        auto d =
            platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {32, 18}});
        ASSERT_TRUE(d.ok()) << d.error().message;
        display_ = std::move(d).value();
        world_.insert_resource<gpu::Device>();
    }
    Result<void> add(std::initializer_list<std::string> sets) {
        world_.insert_resource<params::Params>(test::make_params(sets));
        world_.insert_resource<RenderTarget>().target = display_->frame_target();
        return add_puddle_plugin(world_, schedule_);
    }
    std::unique_ptr<platform::Display> display_;  // the context outlives the world's GPU objects
    ecs::World world_;
    ecs::Schedule schedule_;
};

TEST_F(PuddlePluginTest, RegistersItsSystemsWithTheirStagesAndConditions) {
    const auto added = add({"wave.resolution=64"});
    ASSERT_TRUE(added.ok()) << added.error().message;
    EXPECT_EQ(schedule_.describe(), test::puddle_plugin_schedule);
}

TEST_F(PuddlePluginTest, BuildsTheResourcesItsSystemsRead) {
    const auto added = add({"wave.resolution=64", "scene.kind=ocean"});
    ASSERT_TRUE(added.ok()) << added.error().message;
    EXPECT_EQ(world_.resource<WaveField>().resolution, 64);
    EXPECT_EQ(world_.resource<ShownLook>().scene, Scene::ocean) << "the look the config chose";
    EXPECT_EQ(world_.resource<Surface>().resolution, 64) << "the surface matches the field";
}

TEST_F(PuddlePluginTest, ASkyThatDoesNotLoadStopsItWithTheAssetError) {
    const auto added = add({"environment.image=/nonexistent/sky.hdr"});
    ASSERT_FALSE(added.ok());
    EXPECT_EQ(added.error().code, ExitCode::Asset);
    EXPECT_NE(added.error().message.find("/nonexistent/sky.hdr"), std::string::npos) << added.error().message;
    EXPECT_TRUE(schedule_.describe().empty()) << "nothing registered";
}

}  // namespace
}  // namespace puddle::systems
