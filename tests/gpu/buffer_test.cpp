// Uniform buffers (gpu/buffer.hpp): bytes written through Buffer::write reach a shader's uniform block,
// a write at an offset replaces only its own bytes, and the size is what was asked for. The shader is the
// wave step (wave_step.frag): on a still field, each texel under a drop becomes 0.5 * its strength.
#include "gpu/buffer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class BufferTest : public test::DeviceFixture {
protected:
    static constexpr int size = 8;
    void SetUp() override {
        DeviceFixture::SetUp();
        if (HasFatalFailure()) return;
        if (!device_->caps().float_render_targets) GTEST_SKIP() << "needs RG32F render targets";
        auto still = device_->create_texture(
            {.label = "still field", .format = TextureFormat::RG32F, .width = size, .height = size});
        auto out = device_->create_texture({.label = "stepped field",
                                            .format = TextureFormat::RG32F,
                                            .width = size,
                                            .height = size,
                                            .render_target = true});
        auto step = device_->create_pipeline({.label = "wave step",
                                              .fragment = "wave_step.frag",
                                              .defines = {"MAX_DROPS 4"},
                                              .textures = {"u_field"},
                                              .uniform_blocks = {"Drops"}});
        ASSERT_TRUE(still.ok() && out.ok() && step.ok());
        const std::vector<float> zeros(size * size * 2, 0.0f);
        still->upload(std::as_bytes(std::span(zeros)));
        still_ = std::move(still).value();
        out_ = std::move(out).value();
        step_ = std::move(step).value();
    }

    // One wave step over the still field with `count` drops from `drops`; the new height per texel.
    std::vector<float> step(const Buffer& drops, int count) {
        const Sampler nearest =
            device_->create_sampler({.label = "nearest", .min = Filter::Nearest, .mag = Filter::Nearest});
        device_->begin_pass({.label = "step", .target = {&out_, {size, size}}, .load = LoadOp::DontCare})
            .set_pipeline(step_)
            .set_texture(0, still_, nearest)
            .set_uniform_buffer(0, drops)
            .set("u_wave_damping", 1.0f)
            .set("u_drop_count", count)
            .draw_fullscreen();
        const std::vector<float> rgba = device_->read_texture(out_);
        std::vector<float> heights;
        for (std::size_t i = 0; i < rgba.size(); i += 4) heights.push_back(rgba[i]);
        return heights;
    }
    static float at(const std::vector<float>& heights, int x, int y) {
        return heights[std::size_t(y * size + x)];
    }

    Texture still_, out_;
    Pipeline step_;
};

// A drop in std140: vec4 (x, y in texels; z = strength; w unused), 16 bytes.
using Drop = std::array<float, 4>;

// Fails if write() ignored the offset (the second drop would land on the first).
TEST_F(BufferTest, BytesWrittenReachTheShadersUniformBlock) {
    auto drops = device_->create_buffer({.label = "drops", .size = 4 * sizeof(Drop)});
    ASSERT_TRUE(drops.ok()) << drops.error().message;
    EXPECT_EQ(drops->size(), 4 * sizeof(Drop));
    const Drop first{2.5f, 3.5f, 0.5f, 0}, second{6.5f, 1.5f, 1.0f, 0};  // texel centres (2, 3) and (6, 1)
    drops->write(std::as_bytes(std::span(&first, 1)));
    drops->write(std::as_bytes(std::span(&second, 1)), sizeof(Drop));
    const std::vector<float> both = step(*drops, 2);
    EXPECT_FLOAT_EQ(at(both, 2, 3), 0.5f * first[2]);
    EXPECT_FLOAT_EQ(at(both, 6, 1), 0.5f * second[2]);
    EXPECT_FLOAT_EQ(at(both, 0, 7), 0.0f) << "far from both drops";
    EXPECT_EQ(at(step(*drops, 1), 6, 1), 0.0f) << "u_drop_count 1 reads the first only";
}

// Fails if write() rewrote from byte 0 or reallocated (the first drop would be lost).
TEST_F(BufferTest, AWriteAtAnOffsetReplacesOnlyItsBytes) {
    auto drops = device_->create_buffer({.label = "drops", .size = 2 * sizeof(Drop)});
    ASSERT_TRUE(drops.ok()) << drops.error().message;
    const std::array<Drop, 2> initial{Drop{2.5f, 3.5f, 0.5f, 0}, Drop{6.5f, 1.5f, 1.0f, 0}};
    drops->write(std::as_bytes(std::span(initial)));
    const float stronger = 3.0f;  // only the second drop's strength: 4 bytes at offset 16 + 8
    drops->write(std::as_bytes(std::span(&stronger, 1)), sizeof(Drop) + 2 * sizeof(float));
    const std::vector<float> heights = step(*drops, 2);
    EXPECT_FLOAT_EQ(at(heights, 2, 3), 0.5f * initial[0][2]);
    EXPECT_FLOAT_EQ(at(heights, 6, 1), 0.5f * stronger);
}

}  // namespace
}  // namespace puddle::gpu
