// The per-pixel cost estimate the benchmark prints (bench/shader_cost.hpp): exact counts on small shaders,
// and the orderings that matter on the real one.
#include "bench/shader_cost.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu/shader_source.hpp"
#include "params/param_store.hpp"
#include "render/puddle_variant.hpp"

namespace puddle::bench {
namespace {

TEST(ShaderCost, CountsFetchesOperatorsAndBuiltins) {
    const ShaderCost c = estimate_shader_cost(R"(
        uniform sampler2D u_a;   // texture(u_a, v) in a comment does not count
        out vec4 o;
        void main() {
            vec3 x = texture(u_a, vec2(0.5)).rgb * 2.0 + 1.0;   /* 1 fetch, 2 ops */
            o = vec4(normalize(x), 1.0);                         // normalize: 3
        })");
    EXPECT_EQ(c.texture_fetches, 1);
    EXPECT_EQ(c.alu_ops, 5);
}

TEST(ShaderCost, CountsUserFunctionsAtEveryCallAndLoopsByTripCount) {
    const ShaderCost c = estimate_shader_cost(R"(
        uniform sampler2D u_a;
        float h(vec2 p) { return texture(u_a, p).r * 3.0; }
        void main() {
            float s = h(vec2(0.0));
            for (int i = 0; i < 4; ++i) s += h(vec2(s));
        })");
    EXPECT_EQ(c.texture_fetches, 5);
    EXPECT_EQ(c.alu_ops, 1 + 4 * 2);
    EXPECT_EQ(estimate_shader_cost("void main() { for (int i = 0; i < 64; ++i) { x += 1.0; } }", 14).alu_ops,
              14);
}

TEST(ShaderCost, FollowsTheVariantsDefines) {
    const std::string source = R"(
        #define FAST
        uniform sampler2D u_a;
        void main() {
        #ifdef FAST
            o = texture(u_a, p);
        #else
            o = texture(u_a, p) + texture(u_a, q);
        #endif
        })";
    EXPECT_EQ(estimate_shader_cost(source).texture_fetches, 1);
}

// #if defined / #elif defined / #else: exactly one branch counts, the first whose condition holds.
TEST(ShaderCost, FollowsElifChains) {
    const auto fetches = [](const std::string& define) {
        return estimate_shader_cost(define + R"(
            uniform sampler2D u_a;
            void main() {
            #if defined(ONE)
                o = texture(u_a, p);
            #elif defined(TWO)
                o = texture(u_a, p) + texture(u_a, q);
            #elif defined(ONE)
                o = texture(u_a, p) + texture(u_a, q) + texture(u_a, r) + texture(u_a, s);
            #else
                o = texture(u_a, p) + texture(u_a, q) + texture(u_a, r);
            #endif
            })")
            .texture_fetches;
    };
    EXPECT_EQ(fetches("#define ONE\n"), 1);
    EXPECT_EQ(fetches("#define TWO\n"), 2);
    EXPECT_EQ(fetches(""), 3);
}

// The variant the default parameters select: the setts (drawn, no texture), no RGBM, the soft tone curve.
TEST(ShaderCost, PuddleIntersectCostsLessThanRaymarch) {
    render::PuddleVariant v = render::choose_puddle_variant(params::Params{}, false);
    auto intersect = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
    v.raymarch = true;
    auto raymarch = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
    ASSERT_TRUE(intersect.ok() && raymarch.ok());
    const ShaderCost i = estimate_shader_cost(intersect->source, 14),
                     r = estimate_shader_cost(raymarch->source, 14);
    EXPECT_EQ(i.texture_fetches, 2);   // the surface once, the sky once (reflected or direct)
    EXPECT_GT(r.texture_fetches, 14);  // a surface read per march step
    EXPECT_GT(r.alu_ops, i.alu_ops);
}

// The image ground costs a fetch the checkerboard and the setts do not; a hidden ground costs none of
// their work.
TEST(ShaderCost, GroundVariantsCarryOnlyTheirOwnWork) {
    render::PuddleVariant v = render::choose_puddle_variant(params::Params{}, false);
    v.shore = false;  // a hidden ground is the box's only: beside a shore the stones always show
    const auto cost = [&](render::GroundKind g) {
        v.ground = g;
        auto s = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
        return s ? estimate_shader_cost(s->source, 14) : ShaderCost{};
    };
    const ShaderCost checker = cost(render::GroundKind::Checkerboard),
                     setts = cost(render::GroundKind::Paving), image = cost(render::GroundKind::Image),
                     hidden = cost(render::GroundKind::Hidden);
    EXPECT_EQ(image.texture_fetches, checker.texture_fetches + 1);
    EXPECT_EQ(setts.texture_fetches, checker.texture_fetches);
    EXPECT_GT(setts.alu_ops, checker.alu_ops);
    EXPECT_LT(hidden.alu_ops, setts.alu_ops);
    EXPECT_EQ(hidden.texture_fetches, checker.texture_fetches);
    EXPECT_LT(hidden.alu_ops, checker.alu_ops);
}

// Issue 31's budget for the default look on a Raspberry Pi 4: at most 260 ALU ops and 4 fetches a pixel
// (with the adaptive scale that holds 60 fps there). README "Shader cost" says where it went.
TEST(ShaderCost, TheDefaultLookStaysWithinThePi4Budget) {
    // The procedural sky with its drifting clouds, as a GPU with half-float render targets shows it.
    const render::PuddleVariant v = render::choose_puddle_variant(params::Params{}, false, true);
    ASSERT_TRUE(v.shore) << "the default is the shore";
    ASSERT_TRUE(v.cloud_layer) << "and the clouds drift";
    auto s = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
    ASSERT_TRUE(s.ok());
    const ShaderCost c = estimate_shader_cost(s->source, 14);
    EXPECT_LE(c.alu_ops, 260);
    EXPECT_LE(c.texture_fetches, 4);
    RecordProperty("alu_ops", c.alu_ops);
    RecordProperty("texture_fetches", c.texture_fetches);
}

}  // namespace
}  // namespace puddle::bench
