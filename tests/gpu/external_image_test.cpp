// Tests for src/gpu/external_image.hpp on a real context: an ExternalImage made from a GL texture
// (EGL_KHR_gl_texture_2D_image, the path llvmpipe has in place of dmabuf import) sampled through the
// external sampler gives the texture's texels, and shares their storage rather than copying them; the
// handle is move-only; an image EGL refuses is an error naming it and the call.
#include "gpu/external_image.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "gpu/device.hpp"
#include "gpu/render_pass.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

constexpr int width = 4, height = 2;

class ExternalImageTest : public test::DeviceFixture {
protected:
    void SetUp() override {
        test::DeviceFixture::SetUp();
        if (HasFatalFailure()) return;
        const ExternalImageSupport support = device_->external_image_support();
        if (!support.external_sampler || !support.texture_images)
            GTEST_SKIP() << "needs GL_OES_EGL_image_external_essl3 and EGL_KHR_gl_texture_2D_image";
        source_ =
            device_->create_texture({.label = "image source", .width = width, .height = height}).value();
    }

    // The image drawn through samplerExternalOES (camera_convert.frag, EXTERNAL_OES) into an sRGB target:
    // the shader decodes sRGB and the target encodes it again, so the bytes come back within one step.
    std::vector<float> sample(const ExternalImage& image) {
        auto pipeline = device_->create_pipeline({.label = "external sample",
                                                  .fragment = "camera_convert.frag",
                                                  .defines = {"EXTERNAL_OES"},
                                                  .textures = {"u_external"}});
        EXPECT_TRUE(pipeline.ok()) << (pipeline.ok() ? "" : pipeline.error().message);
        if (!pipeline.ok()) return {};
        const Texture target = device_
                                   ->create_texture({.label = "sampled",
                                                     .format = TextureFormat::SRGB8_A8,
                                                     .width = width,
                                                     .height = height,
                                                     .render_target = true})
                                   .value();
        const Sampler nearest =
            device_->create_sampler({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest});
        device_
            ->begin_pass(
                {.label = "sample external", .target = {&target, {width, height}}, .load = LoadOp::Clear})
            .set_pipeline(*pipeline)
            .set_texture(0, image.texture(), nearest)
            .set("u_size", glm::vec2(width, height))
            .draw_fullscreen();
        return device_->read_texture(target);
    }

    void upload(const std::vector<std::uint8_t>& rgba) { source_.upload(std::as_bytes(std::span(rgba))); }

    // Each texel of `out` (floats, GL row order) against `rgba` (bytes, the same order), within one step.
    static void expect_texels(const std::vector<float>& out, const std::vector<std::uint8_t>& rgba) {
        ASSERT_EQ(out.size(), rgba.size());
        for (std::size_t i = 0; i < rgba.size(); ++i)
            EXPECT_NEAR(std::lround(out[i] * 255.0f), rgba[i], 1)
                << "texel " << i / 4 << " (x " << (i / 4) % width << ", row " << (i / 4) / width
                << ") channel " << i % 4;
    }

    Texture source_;
};

// Eight different texels; the two rows differ, so a flipped or shifted sample shows.
const std::vector<std::uint8_t> first_texels = {255, 0,   0,   255, 0,   255, 0,   255, 0,   0,   255,
                                                255, 255, 255, 255, 255, 10,  20,  30,  255, 128, 64,
                                                32,  255, 0,   0,   0,   255, 200, 180, 90,  255};

TEST_F(ExternalImageTest, SamplingTheImageGivesTheSourcesTexels) {
    upload(first_texels);
    auto image = device_->create_external_image({.label = "camera frame", .source = &source_});
    ASSERT_TRUE(image.ok()) << image.error().message;
    EXPECT_TRUE(static_cast<bool>(*image));
    EXPECT_EQ(image->texture().desc().kind, TextureKind::External);
    EXPECT_EQ(image->texture().width(), width);
    EXPECT_EQ(image->texture().height(), height);
    expect_texels(sample(*image), first_texels);
}

TEST_F(ExternalImageTest, TheImageSharesTheSourcesStorage) {
    upload(first_texels);
    auto image = device_->create_external_image({.label = "camera frame", .source = &source_});
    ASSERT_TRUE(image.ok()) << image.error().message;
    // New texels in the source after the image was made: the image shows them (an EGLImage is the
    // texture's storage, not a copy of it).
    std::vector<std::uint8_t> second(first_texels.rbegin(), first_texels.rend());
    for (std::size_t i = 3; i < second.size(); i += 4) second[i] = 255;
    upload(second);
    expect_texels(sample(*image), second);
}

TEST_F(ExternalImageTest, MovingTheImageMovesItsTexture) {
    upload(first_texels);
    auto made = device_->create_external_image({.label = "camera frame", .source = &source_});
    ASSERT_TRUE(made.ok()) << made.error().message;
    ExternalImage first = std::move(made).value();
    const std::uint32_t id = first.texture().id();
    ExternalImage second = std::move(first);
    EXPECT_FALSE(static_cast<bool>(first));  // NOLINT(bugprone-use-after-move): what a move leaves
    EXPECT_FALSE(static_cast<bool>(first.texture()));
    EXPECT_EQ(second.texture().id(), id);
    expect_texels(sample(second), first_texels);
}

TEST_F(ExternalImageTest, AnImageEglRefusesIsAnErrorNamingItAndTheCall) {
    // A dmabuf without a file descriptor: EGL refuses it whether or not it can import dmabufs.
    auto image = device_->create_external_image(
        {.label = "no fd", .format = DmabufFormat::Yuyv, .width = width, .height = height});
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().code, ExitCode::Runtime);
    EXPECT_TRUE(image.error().message.starts_with("gpu: external image 'no fd': eglCreateImageKHR: EGL_BAD_"))
        << image.error().message;
}

}  // namespace
}  // namespace puddle::gpu
