// The per-pixel cost estimate the benchmark prints (gpu/shader_cost.hpp): exact counts on small shaders,
// and the orderings that matter on the real one.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu/shader_cost.hpp"
#include "gpu/shader_source.hpp"

namespace puddle::gpu {
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
    EXPECT_EQ(estimate_shader_cost("void main() { for (int i = 0; i < 64; ++i) { x += 1.0; } }", 14).alu_ops, 14);
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

TEST(ShaderCost, PuddleIntersectCostsLessThanRaymarch) {
    auto intersect = assemble_shader("puddle.frag", {});
    const std::vector<std::string> raymarch_defines{"METHOD_RAYMARCH"};
    auto raymarch = assemble_shader("puddle.frag", raymarch_defines);
    ASSERT_TRUE(intersect.ok() && raymarch.ok());
    const ShaderCost i = estimate_shader_cost(intersect->source, 14), r = estimate_shader_cost(raymarch->source, 14);
    EXPECT_GE(i.texture_fetches, 4);  // surface at least three times, environment, ground
    EXPECT_GT(r.texture_fetches, i.texture_fetches);
    EXPECT_GT(r.alu_ops, i.alu_ops);
}

}  // namespace
}  // namespace puddle::gpu
