// Pipelines (gpu/pipeline.hpp): how Blend::Alpha and Blend::Replace meet what the target holds, and the
// uniforms a linked pipeline reports. Compile and link errors are the Device's (device_test.cpp).
#include "gpu/pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class PipelineTest : public test::DeviceFixture {};

// 8-bit channel values as the blend unit sees them.
float unit(int byte) {
    return static_cast<float>(byte) / 255.0f;
}

// GL's alpha blend as set_pipeline asks for it: colour src * a + dst * (1 - a), alpha kept from dst.
glm::u8vec4 alpha_over(glm::u8vec4 src, glm::u8vec4 dst) {
    const float a = unit(src.a);
    auto mix = [&](int s, int d) { return std::lround((unit(s) * a + unit(d) * (1 - a)) * 255.0f); };
    return glm::u8vec4(mix(src.r, dst.r), mix(src.g, dst.g), mix(src.b, dst.b), dst.a);
}

void expect_within_one(glm::u8vec4 got, glm::u8vec4 want) {
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(got[c], want[c], 1) << "channel " << c << ": got " << testing::PrintToString(got)
                                        << ", want " << testing::PrintToString(want);
}

// Fails with blending off (the source alone comes out) or with GL_ONE_MINUS_SRC_ALPHA for alpha too (the
// target's alpha 128 would rise).
TEST_F(PipelineTest, AlphaBlendMixesByTheSourcesAlphaAndKeepsTheTargetsAlpha) {
    const glm::u8vec4 dst{51, 102, 204, 128};  // the clear colour below, in bytes
    for (const glm::u8vec4 src : {glm::u8vec4{255, 0, 0, 64}, glm::u8vec4{10, 240, 30, 200}}) {
        Texture t = test::make_target(*device_, {4, 4}, glm::vec4(dst) / 255.0f);
        test::draw_texture(*device_, t, test::make_copy_pipeline(*device_, Blend::Alpha),
                           test::make_texels(*device_, {src}));
        for (const glm::u8vec4 texel : test::read_texels(*device_, t))
            expect_within_one(texel, alpha_over(src, dst));
    }
}

TEST_F(PipelineTest, ReplaceWritesTheOutputAlphaAndAll) {
    Texture t = test::make_target(*device_, {4, 4}, {0.2f, 0.4f, 0.8f, 0.5f});
    const glm::u8vec4 src{255, 0, 0, 64};
    test::draw_texture(*device_, t, test::make_copy_pipeline(*device_, Blend::Replace),
                       test::make_texels(*device_, {src}));
    EXPECT_EQ(test::read_texels(*device_, t), std::vector(16, src));
}

// set_pipeline sets the blend state each time: a Replace pipeline after an Alpha one in the same pass
// replaces. Fails if set_pipeline only enabled blending and never disabled it.
TEST_F(PipelineTest, AReplacePipelineAfterAnAlphaOneTurnsBlendingOff) {
    Texture t = test::make_target(*device_, {4, 4}, {0, 0, 1, 1});
    const Pipeline alpha = test::make_copy_pipeline(*device_, Blend::Alpha);
    const Pipeline replace = test::make_copy_pipeline(*device_, Blend::Replace);
    const Texture half_red = test::make_texels(*device_, {{255, 0, 0, 128}});
    const Sampler nearest =
        device_->create_sampler({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest});
    device_->begin_pass({.label = "two pipelines", .target = {&t, {4, 4}}, .load = LoadOp::Load})
        .set_pipeline(alpha)
        .set_texture(0, half_red, nearest)
        .set("u_quarter_turns", 0)
        .set("u_brightness", 1.0f)
        .set("u_screen_size", glm::vec2(4, 4))
        .draw_fullscreen();
    ASSERT_NE(test::read_texels(*device_, t)[0].b, 0) << "blended over the blue";
    device_->begin_pass({.label = "two pipelines", .target = {&t, {4, 4}}, .load = LoadOp::Load})
        .set_pipeline(alpha)
        .set_pipeline(replace)
        .set_texture(0, half_red, nearest)
        .set("u_quarter_turns", 0)
        .set("u_brightness", 1.0f)
        .set("u_screen_size", glm::vec2(4, 4))
        .draw_fullscreen();
    EXPECT_EQ(test::read_texels(*device_, t), std::vector(16, glm::u8vec4{255, 0, 0, 128}));
}

TEST_F(PipelineTest, KnowsItsLabelBlendAndActiveUniforms) {
    const Pipeline p = test::make_copy_pipeline(*device_, Blend::Alpha);
    EXPECT_EQ(p.label(), "copy");
    EXPECT_EQ(p.blend(), Blend::Alpha);
    std::vector<std::string> names(p.uniform_names().begin(), p.uniform_names().end());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names,
              (std::vector<std::string>{"u_brightness", "u_canvas", "u_quarter_turns", "u_screen_size"}));
    for (const std::string& name : names) EXPECT_TRUE(p.uniform(name).active()) << name;
    EXPECT_NE(p.location("u_quarter_turns"), p.location("u_screen_size"));
    EXPECT_EQ(p.location("u_no_such_uniform"), -1);
    EXPECT_FALSE(p.uniform("u_no_such_uniform").active());
}

// Arrays are listed by their name without "[0]", so set(name, span) finds them.
TEST_F(PipelineTest, ListsUniformArraysByTheirBareName) {
    auto p = device_->create_pipeline({.label = "ocean", .fragment = "ocean.frag"});
    ASSERT_TRUE(p.ok()) << p.error().message;
    const auto names = p->uniform_names();
    EXPECT_NE(std::find(names.begin(), names.end(), "u_octave_shift"), names.end());
    EXPECT_EQ(std::find_if(names.begin(), names.end(), [](const std::string& n) { return n.ends_with("]"); }),
              names.end());
    EXPECT_TRUE(p->uniform("u_octave_shift").active());
}

}  // namespace
}  // namespace puddle::gpu
