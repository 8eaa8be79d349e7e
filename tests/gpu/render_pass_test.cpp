// Render passes (gpu/render_pass.hpp) on a real context: what each load operation leaves in the target,
// that a row band draws only its rows and leaves later passes whole, that the store and load hints raise no
// GL error, that DontCare runs no clear, and that uniforms set through the pass reach the shader.
#include "gpu/render_pass.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

using test::read_texels;

class RenderPassTest : public test::DeviceFixture {};

constexpr glm::vec4 red{1, 0, 0, 1}, blue{0, 0, 1, 1};
constexpr glm::u8vec4 red8{255, 0, 0, 255}, blue8{0, 0, 255, 255}, green8{0, 255, 0, 255};

// Texels of `image` (rows top first, `width` wide) in rows [first, last] counted from the bottom (GL's row
// 0).
std::vector<glm::u8vec4> gl_rows(const std::vector<glm::u8vec4>& image, int width, int first, int last) {
    const int height = static_cast<int>(image.size()) / width;
    std::vector<glm::u8vec4> out;
    for (int gl_row = first; gl_row <= last; ++gl_row)
        for (int x = 0; x < width; ++x) out.push_back(image[std::size_t((height - 1 - gl_row) * width + x)]);
    return out;
}

std::vector<glm::u8vec4> all(glm::u8vec4 texel, std::size_t count) {
    return std::vector(count, texel);
}

TEST_F(RenderPassTest, ClearFillsEveryPixelWithTheClearColour) {
    Texture t = test::make_target(*device_, {8, 4}, red);
    device_->begin_pass(
        {.label = "clear", .target = {&t, {8, 4}}, .load = LoadOp::Clear, .clear = {0.2f, 0.4f, 0.6f, 0.8f}});
    EXPECT_EQ(read_texels(*device_, t), all({51, 102, 153, 204}, 32));
}

// Flipping LoadOp::Load to Clear in the second pass clears the red to the default black.
TEST_F(RenderPassTest, LoadKeepsWhatTheEarlierPassLeft) {
    Texture t = test::make_target(*device_, {8, 4}, red);
    device_->begin_pass({.label = "load", .target = {&t, {8, 4}}, .load = LoadOp::Load});
    EXPECT_EQ(read_texels(*device_, t), all(red8, 32));
    // A pass that loads and draws over part of it (alpha blending, so the loaded colour is mixed in).
    const Texture half_green = test::make_texels(*device_, {{0, 255, 0, 128}});
    test::draw_texture(*device_, t, test::make_copy_pipeline(*device_, Blend::Alpha), half_green);
    for (const glm::u8vec4 texel : read_texels(*device_, t)) {
        EXPECT_NEAR(texel.r, 127, 1) << "the loaded red, half covered";
        EXPECT_NEAR(texel.g, 128, 1);
        EXPECT_EQ(texel.b, 0);
    }
}

// Flipping LoadOp::Clear to Load in the second pass keeps the red.
TEST_F(RenderPassTest, ClearReplacesWhatTheEarlierPassDrew) {
    Texture t = test::make_target(*device_, {8, 4}, red);
    test::draw_texture(*device_, t, test::make_copy_pipeline(*device_, Blend::Replace),
                       test::make_texels(*device_, {green8}));
    ASSERT_EQ(read_texels(*device_, t), all(green8, 32));
    device_->begin_pass({.label = "clear", .target = {&t, {8, 4}}, .load = LoadOp::Clear, .clear = blue});
    EXPECT_EQ(read_texels(*device_, t), all(blue8, 32));
}

// Rows 2 to 4 of 8 (rows {2, 3}); without the scissor every row turns green.
TEST_F(RenderPassTest, ARowBandDrawsOnlyItsRows) {
    Texture t = test::make_target(*device_, {4, 8}, red);
    const Pipeline copy = test::make_copy_pipeline(*device_, Blend::Replace);
    const Texture green = test::make_texels(*device_, {green8});
    const Sampler nearest =
        device_->create_sampler({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest});
    device_->begin_pass({.label = "band", .target = {&t, {4, 8}}, .load = LoadOp::Load, .rows = {2, 3}})
        .set_pipeline(copy)
        .set_texture(0, green, nearest)
        .set("u_quarter_turns", 0)
        .set("u_brightness", 1.0f)
        .set("u_screen_size", glm::vec2(4, 8))
        .draw_fullscreen();
    const auto texels = read_texels(*device_, t);
    EXPECT_EQ(gl_rows(texels, 4, 0, 1), all(red8, 8)) << "below the band";
    EXPECT_EQ(gl_rows(texels, 4, 2, 4), all(green8, 12)) << "the band, rows 2 to 4";
    EXPECT_EQ(gl_rows(texels, 4, 5, 7), all(red8, 12)) << "above the band";
}

// A cleared band clears its rows only; the next pass without a band clears every row, which fails if
// end() left the scissor test on.
TEST_F(RenderPassTest, ABandedClearClearsItsRowsAndLaterPassesAreWhole) {
    Texture t = test::make_target(*device_, {4, 8}, red);
    device_->begin_pass(
        {.label = "band", .target = {&t, {4, 8}}, .load = LoadOp::Clear, .clear = blue, .rows = {6, 2}});
    const auto banded = read_texels(*device_, t);
    EXPECT_EQ(gl_rows(banded, 4, 0, 5), all(red8, 24));
    EXPECT_EQ(gl_rows(banded, 4, 6, 7), all(blue8, 8));
    device_->begin_pass(
        {.label = "whole", .target = {&t, {4, 8}}, .load = LoadOp::Clear, .clear = {0, 1, 0, 1}});
    EXPECT_EQ(read_texels(*device_, t), all(green8, 32));
}

// glInvalidateFramebuffer takes GL_COLOR_ATTACHMENT0 for a texture's framebuffer and GL_COLOR only for
// framebuffer 0 (GLES 3.0 section 4.5): naming the wrong one raises GL_INVALID_ENUM.
TEST_F(RenderPassTest, DontCareAndDiscardOnATextureRaiseNoGlError) {
    Texture t = test::make_target(*device_, {8, 4}, red);
    ASSERT_EQ(device_->take_errors(), "");
    device_->begin_pass(
        {.label = "discarded", .target = {&t, {8, 4}}, .load = LoadOp::DontCare, .store = StoreOp::Discard});
    EXPECT_EQ(device_->take_errors(), "");
    // The hints leave the target usable: a later pass renders into it as before.
    device_->begin_pass({.label = "clear", .target = {&t, {8, 4}}, .load = LoadOp::Clear, .clear = blue});
    EXPECT_EQ(read_texels(*device_, t), all(blue8, 32));
}

// DontCare tells the driver that the old contents need not be kept, and must not cost a clear (a full
// write of the target). What the target holds afterwards is undefined, so the observable is what it does
// not hold: the pass's clear colour, in any texel. (On llvmpipe, where invalidation is a no-op, the red
// stays.) Were DontCare run as a clear, every texel would be blue.
TEST_F(RenderPassTest, DontCareDoesNotClear) {
    Texture t = test::make_target(*device_, {8, 4}, red);
    device_->begin_pass(
        {.label = "dont care", .target = {&t, {8, 4}}, .load = LoadOp::DontCare, .clear = blue});
    for (const glm::u8vec4 texel : read_texels(*device_, t)) EXPECT_NE(texel, blue8);
    EXPECT_EQ(device_->take_errors(), "");
}

// Framebuffer 0 takes GL_COLOR, not GL_COLOR_ATTACHMENT0, for the same hints (GLES 3.0 section 4.5; the
// headless context has no surface, so framebuffer 0 is GL's incomplete default one, which still checks
// the attachment names): the other name raises GL_INVALID_ENUM.
TEST_F(RenderPassTest, DontCareAndDiscardOnFramebufferZeroRaiseNoGlError) {
    ASSERT_EQ(device_->take_errors(), "");
    device_->begin_pass({.label = "surface",
                         .target = {nullptr, {64, 32}},
                         .load = LoadOp::DontCare,
                         .store = StoreOp::Discard});
    EXPECT_EQ(device_->take_errors(), "");
}

// Uniforms by name and by looked-up location reach the shader: u_screen_size scales the lookup (twice the
// target: every pixel samples the left texel) and u_quarter_turns 2 turns the picture (left and right swap).
TEST_F(RenderPassTest, UniformsSetOnThePassReachTheShader) {
    Texture t = test::make_target(*device_, {4, 2}, red);
    const Pipeline copy = test::make_copy_pipeline(*device_, Blend::Replace);
    const Texture blue_green = test::make_texels(*device_, {blue8, green8});
    const Sampler nearest =
        device_->create_sampler({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest});
    auto draw = [&](glm::vec2 screen, int turns) {
        device_->begin_pass({.label = "copy", .target = {&t, {4, 2}}, .load = LoadOp::Clear})
            .set_pipeline(copy)
            .set_texture(0, blue_green, nearest)
            .set(copy.uniform("u_quarter_turns"), turns)
            .set("u_brightness", 1.0f)
            .set("u_screen_size", screen)
            .set("u_not_in_this_shader", 1.0f)
            .draw_fullscreen();
        return read_texels(*device_, t);
    };
    const std::vector<glm::u8vec4> halves{blue8, blue8, green8, green8, blue8, blue8, green8, green8};
    EXPECT_EQ(draw({4, 2}, 0), halves);
    EXPECT_EQ(draw({8, 4}, 0), all(blue8, 8));
    const std::vector<glm::u8vec4> turned{green8, green8, blue8, blue8, green8, green8, blue8, blue8};
    EXPECT_EQ(draw({4, 2}, 2), turned);
    EXPECT_EQ(device_->take_errors(), "") << "a name the shader does not use is ignored";
}

}  // namespace
}  // namespace puddle::gpu
