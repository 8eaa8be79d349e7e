// Which puddle shader variant the parameters select, and that every variant has its own slot and defines.
#include "render/puddle_variant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "params/config_loader.hpp"

namespace puddle::render {
namespace {

using params::ParamId;

params::Params with(std::initializer_list<std::string> sets) {
    params::Params p;
    for (const std::string& s : sets) {
        auto e = params::parse_assignment(s);
        EXPECT_TRUE(e.ok()) << s;
        if (e) p.set(e->id, e->value, params::ParamSource::CommandLine);
    }
    return p;
}

bool has(const std::vector<std::string>& defines, const std::string& d) {
    return std::find(defines.begin(), defines.end(), d) != defines.end();
}

// The default look is the wet paving (the setts, drawn by the shader); the reference preset brings back the
// checkerboard.
TEST(PuddleVariant, DefaultsSelectTheCheapPath) {
    const PuddleVariant v = choose_puddle_variant(with({}), false);
    EXPECT_FALSE(v.raymarch);
    EXPECT_EQ(v.ground, GroundKind::Paving);
    EXPECT_FALSE(v.env_rgbm);
    EXPECT_EQ(v.tonemap, params::Tonemap::soft);
}

TEST(PuddleVariant, EachParameterPicksItsVariant) {
    EXPECT_TRUE(choose_puddle_variant(with({"render.method=raymarch"}), false).raymarch);
    EXPECT_TRUE(choose_puddle_variant(with({}), false).shore);
    EXPECT_FALSE(choose_puddle_variant(with({"puddle.shape=box"}), false).shore);
    EXPECT_FALSE(choose_puddle_variant(with({"render.method=raymarch"}), false).shore) << "intersect only";
    EXPECT_EQ(choose_puddle_variant(with({"ground.checkerboard=true"}), false).ground,
              GroundKind::Checkerboard);
    EXPECT_EQ(choose_puddle_variant(with({"ground.image=/srv/stones.jpg"}), false).ground, GroundKind::Image);
    EXPECT_EQ(choose_puddle_variant(with({"ground.image=/srv/stones.jpg", "ground.checkerboard=true"}), false)
                  .ground,
              GroundKind::Checkerboard);
    EXPECT_TRUE(choose_puddle_variant(with({}), true).env_rgbm);
    EXPECT_TRUE(choose_puddle_variant(with({}), false, true).cloud_layer);
    EXPECT_FALSE(choose_puddle_variant(with({}), true, true).cloud_layer)
        << "an RGBM cube has no room for them";
    EXPECT_EQ(choose_puddle_variant(with({"look.tonemap=aces"}), false).tonemap, params::Tonemap::aces);
    EXPECT_EQ(choose_puddle_variant(with({"look.tonemap=clip"}), false).tonemap, params::Tonemap::clip);
}

// The ground is hidden when even the shortest path through the water (from the lowest trough straight
// down to the ground) leaves it under 1/4096 of an image's brightness (0.6).
TEST(PuddleVariant, GroundHiddenOnlyWhenTurbidityLeavesNothingVisible) {
    EXPECT_FALSE(ground_hidden(with({})));
    EXPECT_FALSE(ground_hidden(with({"water.turbidity=0.6"})));  // the still_night preset: ground still shows
    // Default box (top at 5), height scale 0.4 (troughs down to 3.4), depth 4: the shortest path is 7.4.
    const float edge = std::log(0.6f * 4096.0f) / 7.4f;  // about 1.05
    EXPECT_FALSE(ground_hidden(with({"water.turbidity=" + std::to_string(edge - 0.01f)})));
    EXPECT_TRUE(ground_hidden(with({"water.turbidity=" + std::to_string(edge + 0.01f)})));
    // A deeper puddle hides the ground at a lower turbidity; bigger waves bring it closer again.
    EXPECT_TRUE(ground_hidden(with({"water.turbidity=0.5", "puddle.depth=20"})));
    EXPECT_FALSE(ground_hidden(with({"water.turbidity=1.2", "wave.height_scale=2"})));
    const PuddleVariant v = choose_puddle_variant(
        with({"water.turbidity=2", "ground.checkerboard=false", "puddle.shape=box"}), false);
    EXPECT_EQ(v.ground, GroundKind::Hidden);  // whatever the ground is, none of it shows
    // Beside a shore the ground shows whatever the water hides.
    const PuddleVariant shore =
        choose_puddle_variant(with({"water.turbidity=2", "ground.checkerboard=false"}), false);
    EXPECT_TRUE(shore.shore);
    EXPECT_EQ(shore.ground, GroundKind::Paving);
}

TEST(PuddleVariant, EveryVariantHasItsOwnSlotAndDefines) {
    std::set<std::size_t> slots;
    std::set<std::vector<std::string>> defines;
    for (bool raymarch : {false, true})
        for (bool shore : {false, true})
            for (GroundKind g :
                 {GroundKind::Checkerboard, GroundKind::Paving, GroundKind::Image, GroundKind::Hidden})
                for (bool rgbm : {false, true})
                    for (bool clouds : {false, true})
                        for (int t = 0; t < static_cast<int>(tonemap_count); ++t) {
                            const PuddleVariant v{.raymarch = raymarch,
                                                  .shore = shore,
                                                  .ground = g,
                                                  .env_rgbm = rgbm,
                                                  .cloud_layer = clouds,
                                                  .tonemap = static_cast<params::Tonemap>(t)};
                            const std::size_t i = variant_index(v);
                            EXPECT_LT(i, puddle_variant_count);
                            slots.insert(i);
                            const auto d = variant_defines(v, false);
                            defines.insert(d);
                            EXPECT_EQ(has(d, "METHOD_RAYMARCH"), raymarch);
                            EXPECT_EQ(has(d, "SHORE"), shore);
                            EXPECT_EQ(has(d, "GROUND_PAVING"), g == GroundKind::Paving);
                            EXPECT_EQ(has(d, "GROUND_IMAGE"), g == GroundKind::Image);
                            EXPECT_EQ(has(d, "GROUND_HIDDEN"), g == GroundKind::Hidden);
                            EXPECT_EQ(has(d, "ENV_RGBM"), rgbm);
                            EXPECT_EQ(has(d, "CLOUD_LAYER"), clouds);
                            EXPECT_TRUE(has(d, "TONEMAP " + std::to_string(t)));
                            EXPECT_FALSE(has(d, "SURFACE_UNORM"));
                            EXPECT_TRUE(has(variant_defines(v, true), "SURFACE_UNORM"));
                        }
    EXPECT_EQ(slots.size(), puddle_variant_count);
    EXPECT_EQ(defines.size(), puddle_variant_count);
}

TEST(PuddleVariant, DescribeNamesTheChoices) {
    EXPECT_EQ(describe({.raymarch = true,
                        .ground = GroundKind::Image,
                        .env_rgbm = true,
                        .tonemap = params::Tonemap::reinhard}),
              "raymarch, ground image, RGBM sky, reinhard tone curve");
    EXPECT_EQ(describe({}), "intersect, checkerboard, clip tone curve");
}

}  // namespace
}  // namespace puddle::render
