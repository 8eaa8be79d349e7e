// The puddle shader's variants on the GPU: every one compiles, and skipping the refraction where
// turbidity hides the ground changes the picture by at most one 8-bit level.
#include <gtest/gtest.h>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"
#include "systems/puddle/render_system.hpp"

namespace puddle::test {
namespace {

using render::GroundKind;
using render::PuddleVariant;

TEST(PuddleVariants, EveryVariantCompiles) {
    auto engine = make_engine(make_params({}), {64, 36});
    ASSERT_TRUE(engine);
    auto& renderer = engine->world().resource<systems::PuddleRenderer>();
    gpu::Device& device = engine->device();
    for (bool raymarch : {false, true})
        for (GroundKind g :
             {GroundKind::Checkerboard, GroundKind::Paving, GroundKind::Image, GroundKind::Hidden})
            for (bool rgbm : {false, true})
                for (int t = 0; t < static_cast<int>(render::tonemap_count); ++t) {
                    const PuddleVariant v{.raymarch = raymarch,
                                          .ground = g,
                                          .env_rgbm = rgbm,
                                          .tonemap = static_cast<params::Tonemap>(t)};
                    EXPECT_NE(renderer.pipeline(device, v), nullptr) << render::describe(v);
                }
}

// Renders `frames` frames with the variant the parameters choose, then the same frame again with `forced`.
struct TwoPictures {
    assets::Image chosen, forced;
    PuddleVariant chosen_variant;
};

TwoPictures render_both(std::initializer_list<std::string> sets, GroundKind forced_ground) {
    TwoPictures out;
    auto engine = make_engine(make_params(sets), {160, 90});
    if (!engine) return out;
    out.chosen = render_frames(*engine, 30);
    ecs::World& w = engine->world();
    const auto& params = w.resource<params::Params>();
    const auto& env = w.resource<systems::Environment>();
    out.chosen_variant = render::choose_puddle_variant(params, env.rgbm, env.cloud_room);
    PuddleVariant forced = out.chosen_variant;
    forced.ground = forced_ground;
    systems::render_system(engine->device(), params, w.resource<systems::Surface>(), env,
                           w.resource<systems::Ground>(), w.resource<systems::Clouds>(),
                           w.resource<systems::PuddleRenderer>(), w.resource<systems::RenderTarget>(),
                           nullptr, &forced);
    out.forced = engine->read_frame();
    return out;
}

TEST(PuddleVariants, HiddenGroundLooksLikeTheFullRefraction) {
    // Turbidity 1.2 over the default 4-unit depth: at most 0.6 * e^-8.9 of the ground shows. In the box:
    // beside a shore the dry ground shows whatever the water hides.
    const TwoPictures p = render_both(
        {"water.turbidity=1.2", "ground.checkerboard=false", "puddle.shape=box", "overlay.rain=false"},
        GroundKind::Paving);
    ASSERT_FALSE(p.chosen.empty());
    EXPECT_EQ(p.chosen_variant.ground, GroundKind::Hidden);
    const ImageDiff d = compare_images(p.chosen, p.forced, 1);
    EXPECT_LE(d.max_channel_diff, 1);
    EXPECT_LT(d.mean_abs_diff, 0.05);
}

// The comparison above can fail: where the ground does show, leaving it out changes the picture.
TEST(PuddleVariants, HidingAVisibleGroundChangesThePicture) {
    const TwoPictures p = render_both(
        {"water.turbidity=0.05", "ground.checkerboard=false", "overlay.rain=false"}, GroundKind::Hidden);
    ASSERT_FALSE(p.chosen.empty());
    EXPECT_EQ(p.chosen_variant.ground, GroundKind::Paving);
    EXPECT_GT(compare_images(p.chosen, p.forced, 4).fraction_over, 0.2);
}

}  // namespace
}  // namespace puddle::test
