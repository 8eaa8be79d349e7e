// The gpu layer on a real (surfaceless) context: capabilities, a compile error that names file:line,
// a pass that clears and reads back, float texture readback.
#include <gtest/gtest.h>

#include <memory>

#include "gpu/device.hpp"
#include "platform/display.hpp"

namespace puddle::gpu {
namespace {

class DeviceTest : public ::testing::Test {
protected:
    void SetUp() override {
        auto d = platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {64, 32}});
        ASSERT_TRUE(d.ok()) << d.error().message;
        display_ = std::move(d).value();
        device_ = std::make_unique<Device>();
    }
    void TearDown() override { device_.reset(); }  // GPU objects before the context
    std::unique_ptr<platform::Display> display_;
    std::unique_ptr<Device> device_;
};

TEST_F(DeviceTest, ProbesCapabilities) {
    const Capabilities& c = device_->caps();
    EXPECT_GE(c.major, 3);
    EXPECT_FALSE(c.renderer.empty());
    EXPECT_EQ(c.float_render_targets, c.major > 3 || c.minor >= 2 || c.has("GL_EXT_color_buffer_float"));
    Device forbidden({.forbid_float_targets = true});
    EXPECT_FALSE(forbidden.caps().float_render_targets);
}

TEST_F(DeviceTest, CompileErrorNamesTheShaderFileAndLine) {
    // A negative array size breaks the line that declares the drops array.
    auto p = device_->create_pipeline({.label = "broken wave",
                                       .fragment = "wave_step.frag",
                                       .defines = {"MAX_DROPS -1"},
                                       .textures = {"u_field"},
                                       .uniform_blocks = {"Drops"}});
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().message.find("broken wave"), std::string::npos) << p.error().message;
    EXPECT_NE(p.error().message.find("wave_step.frag:"), std::string::npos) << p.error().message;
}

TEST_F(DeviceTest, ClearPassReadsBackTopRowFirst) {
    Texture t = device_->create_texture({.label = "target", .format = TextureFormat::RGBA8, .width = 8, .height = 4});
    device_->begin_pass({.label = "clear", .target = {&t, {8, 4}}, .load = LoadOp::Clear, .clear = {1, 0.5f, 0, 1}});
    std::vector<std::uint8_t> rgba(8 * 4 * 4);
    device_->read_pixels({&t, {8, 4}}, rgba);
    EXPECT_EQ(rgba[0], 255);
    EXPECT_NEAR(rgba[1], 128, 1);
    EXPECT_EQ(rgba[2], 0);
    EXPECT_EQ(rgba[3], 255);
}

TEST_F(DeviceTest, FloatAndIntegerTexturesReadBackExactly) {
    Texture f = device_->create_texture({.label = "f", .format = TextureFormat::RG32F, .width = 2, .height = 1});
    const float values[] = {1.5f, -2.25f, 1e-6f, 3.0f};
    f.upload(std::as_bytes(std::span(values)));
    auto back = device_->read_texture(f);
    EXPECT_FLOAT_EQ(back[0], 1.5f);
    EXPECT_FLOAT_EQ(back[1], -2.25f);
    EXPECT_FLOAT_EQ(back[4], 1e-6f);
    Texture i = device_->create_texture({.label = "i", .format = TextureFormat::RG32I, .width = 1, .height = 1});
    const int ints[] = {-70000, 123456};
    i.upload(std::as_bytes(std::span(ints)));
    auto iback = device_->read_texture(i);
    EXPECT_EQ(iback[0], -70000.0f);
    EXPECT_EQ(iback[1], 123456.0f);
}

TEST_F(DeviceTest, TakeErrorsNamesARaisedGlErrorOnceThenIsEmpty) {
    EXPECT_EQ(device_->take_errors(), "") << "a fresh device raised an error";
    // glTexStorage2D refuses a zero width with GL_INVALID_VALUE: a real error, raised through the gpu layer.
    Texture bad = device_->create_texture(
        {.label = "zero width", .format = TextureFormat::RGBA8, .width = 0, .height = 4});
    EXPECT_EQ(device_->take_errors(), "GL_INVALID_VALUE");
    EXPECT_EQ(device_->take_errors(), "") << "taking the errors clears them";
}

}  // namespace
}  // namespace puddle::gpu
