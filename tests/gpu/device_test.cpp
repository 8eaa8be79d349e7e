// The gpu layer on a real (surfaceless) context: capabilities, a compile error that names file:line,
// a pass that clears and reads back, float texture readback, and objects the driver cannot make
// returned as errors naming what was asked for.
#include "gpu/device.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <thread>

#include "platform/display.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class DeviceTest : public test::DeviceFixture {};

TEST_F(DeviceTest, ProbesCapabilities) {
    const Capabilities& c = device_->caps();
    EXPECT_GE(c.major, 3);
    EXPECT_FALSE(c.renderer.empty());
    EXPECT_EQ(c.float_render_targets, c.major > 3 || c.minor >= 2 || c.has("GL_EXT_color_buffer_float"));
    Device forbidden({.forbid_float_targets = true});
    EXPECT_FALSE(forbidden.caps().float_render_targets);
}

// Polls a request the way the frame loop does, for at most 30 s.
std::optional<Result<Pipeline>> wait_for(Device& device, PipelineRequest& request) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < give_up) {
        if (auto built = device.take_pipeline(request)) return built;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return std::nullopt;
}

std::vector<std::uint8_t> draw(Device& device, const Pipeline& pipeline) {
    Texture t =
        device.create_texture({.label = "target", .format = TextureFormat::RGBA8, .width = 64, .height = 32})
            .value();
    device.begin_pass({.label = "draw", .target = {&t, {64, 32}}, .load = LoadOp::Clear})
        .set_pipeline(pipeline)
        .set("u_aspect", 2.0f)
        .draw_fullscreen();
    std::vector<std::uint8_t> rgba(64 * 32 * 4);
    device.read_pixels({&t, {64, 32}}, rgba);
    return rgba;
}

TEST_F(DeviceTest, APipelineLinkedOnTheWorkerDrawsAsOneLinkedHere) {
    auto context = display_->create_worker_context();
    ASSERT_TRUE(context.ok()) << context.error().message;
    device_->start_background_compiles(std::move(context).value());
    const PipelineDesc desc{.label = "street", .fragment = "street.frag"};
    PipelineRequest request = device_->request_pipeline(desc);
    EXPECT_TRUE(request.job) << "queued for the worker, not built on this thread";
    auto built = wait_for(*device_, request);
    ASSERT_TRUE(built && built->ok()) << (built ? built->error().message : "still building after 30 s");
    EXPECT_FALSE(request.active());
    auto here = device_->create_pipeline(desc);
    ASSERT_TRUE(here.ok()) << here.error().message;
    const auto names = (*built)->uniform_names();
    EXPECT_EQ(std::vector<std::string>(names.begin(), names.end()),
              std::vector<std::string>(here->uniform_names().begin(), here->uniform_names().end()));
    const auto worker_pixels = draw(*device_, built->value()), here_pixels = draw(*device_, *here);
    EXPECT_EQ(worker_pixels, here_pixels);
    EXPECT_NE(std::count(worker_pixels.begin(), worker_pixels.end(), 0),
              std::ptrdiff_t(worker_pixels.size()));
}

TEST_F(DeviceTest, ACompileErrorOnTheWorkerNamesTheShaderFileAndLine) {
    auto context = display_->create_worker_context();
    ASSERT_TRUE(context.ok()) << context.error().message;
    device_->start_background_compiles(std::move(context).value());
    PipelineRequest request = device_->request_pipeline({.label = "broken wave",
                                                         .fragment = "wave_step.frag",
                                                         .defines = {"MAX_DROPS -1"},
                                                         .textures = {"u_field"},
                                                         .uniform_blocks = {"Drops"}});
    auto built = wait_for(*device_, request);
    ASSERT_TRUE(built.has_value()) << "still building after 30 s";
    ASSERT_FALSE(built->ok());
    EXPECT_NE(built->error().message.find("wave_step.frag:"), std::string::npos) << built->error().message;
}

// A worker context that cannot be made current (a driver without shared surfaceless contexts).
struct BrokenWorkerContext final : WorkerContext {
    Result<void> make_current() override {
        return make_error(ExitCode::Display, "egl: eglMakeCurrent(worker context): EGL_BAD_MATCH");
    }
    void release() override {}
};

TEST_F(DeviceTest, AWorkerThatCannotStartLeavesPipelinesBuiltHere) {
    device_->start_background_compiles(std::make_unique<BrokenWorkerContext>());
    PipelineRequest request = device_->request_pipeline({.label = "street", .fragment = "street.frag"});
    auto built = wait_for(*device_, request);
    ASSERT_TRUE(built && built->ok()) << (built ? built->error().message : "still building after 30 s");
    EXPECT_NE((*built)->id(), 0u);
    EXPECT_FALSE(device_->compiles_in_background());
    PipelineRequest next = device_->request_pipeline({.label = "street", .fragment = "street.frag"});
    EXPECT_FALSE(next.job) << "built at once from then on";
    EXPECT_TRUE(next.built_now && next.built_now->ok());
}

TEST_F(DeviceTest, ClearPassReadsBackTopRowFirst) {
    Texture t =
        device_->create_texture({.label = "target", .format = TextureFormat::RGBA8, .width = 8, .height = 4})
            .value();
    device_->begin_pass(
        {.label = "clear", .target = {&t, {8, 4}}, .load = LoadOp::Clear, .clear = {1, 0.5f, 0, 1}});
    std::vector<std::uint8_t> rgba(8 * 4 * 4);
    device_->read_pixels({&t, {8, 4}}, rgba);
    EXPECT_EQ(rgba[0], 255);
    EXPECT_NEAR(rgba[1], 128, 1);
    EXPECT_EQ(rgba[2], 0);
    EXPECT_EQ(rgba[3], 255);
}

TEST_F(DeviceTest, FloatAndIntegerTexturesReadBackExactly) {
    Texture f =
        device_->create_texture({.label = "f", .format = TextureFormat::RG32F, .width = 2, .height = 1})
            .value();
    const float values[] = {1.5f, -2.25f, 1e-6f, 3.0f};
    f.upload(std::as_bytes(std::span(values)));
    auto back = device_->read_texture(f);
    EXPECT_FLOAT_EQ(back[0], 1.5f);
    EXPECT_FLOAT_EQ(back[1], -2.25f);
    EXPECT_FLOAT_EQ(back[4], 1e-6f);
    Texture i =
        device_->create_texture({.label = "i", .format = TextureFormat::RG32I, .width = 1, .height = 1})
            .value();
    const int ints[] = {-70000, 123456};
    i.upload(std::as_bytes(std::span(ints)));
    auto iback = device_->read_texture(i);
    EXPECT_EQ(iback[0], -70000.0f);
    EXPECT_EQ(iback[1], 123456.0f);
}

TEST_F(DeviceTest, ATextureBeyondTheGpusLargestSizeIsAnErrorNamingItsSize) {
    const int too_wide = device_->caps().max_texture_size * 2;
    auto t = device_->create_texture({.label = "too wide", .width = too_wide, .height = 4});
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().code, ExitCode::Runtime);
    EXPECT_NE(t.error().message.find(fmt::format("gpu: texture 'too wide' ({}x4 RGBA8, 1 level, ", too_wide)),
              std::string::npos)
        << t.error().message;
    EXPECT_NE(t.error().message.find(fmt::format("): {}x4 is outside 1 to {}, this GPU's largest texture",
                                                 too_wide, device_->caps().max_texture_size)),
              std::string::npos)
        << t.error().message;
    auto cube = device_->create_texture({.label = "sky",
                                         .kind = TextureKind::Cube,
                                         .width = device_->caps().max_cube_map_size * 2,
                                         .height = device_->caps().max_cube_map_size * 2});
    ASSERT_FALSE(cube.ok());
    EXPECT_NE(cube.error().message.find("this GPU's largest cube map face"), std::string::npos)
        << cube.error().message;
}

// More mip levels than a 1x1 texture has: glTexStorage2D refuses (GL_INVALID_OPERATION), and the error
// read after the call comes back instead of a texture without storage.
TEST_F(DeviceTest, AStorageCallTheDriverRefusesIsAnErrorNamingTheGlError) {
    auto t = device_->create_texture({.label = "tiny", .width = 1, .height = 1, .mip_levels = 5});
    ASSERT_FALSE(t.ok());
    EXPECT_EQ(t.error().code, ExitCode::Runtime);
    EXPECT_EQ(t.error().message,
              "gpu: texture 'tiny' (1x1 RGBA8, 5 levels, 20 bytes): glTexStorage2D: GL_INVALID_OPERATION");
    // The error was taken: the next texture is not blamed for it.
    EXPECT_TRUE(
        device_->create_texture({.label = "next", .width = 2, .height = 2, .render_target = true}).ok());
}

// A terabyte uniform buffer: no GPU has it (Mesa refuses more than 4 GiB), so it is out of memory, exit
// code 5.
TEST_F(DeviceTest, ABufferThatDoesNotFitIsAnOutOfMemoryError) {
    auto b = device_->create_buffer({.label = "huge", .size = std::size_t(1) << 40});
    ASSERT_FALSE(b.ok());
    EXPECT_EQ(b.error().code, ExitCode::GpuMemory);
    EXPECT_EQ(b.error().message, "gpu: buffer 'huge' (1099511627776 bytes): glBufferData: GL_OUT_OF_MEMORY");
    EXPECT_TRUE(device_->create_buffer({.label = "small", .size = 64}).ok());
}

TEST_F(DeviceTest, TakeErrorsNamesARaisedGlErrorOnceThenIsEmpty) {
    EXPECT_EQ(device_->take_errors(), "") << "a fresh device raised an error";
    // An upload to a mip level an immutable texture has no storage for: glTexSubImage2D raises
    // GL_INVALID_OPERATION (GLES 3.0 section 3.8.5), a real error through the gpu layer (creation checks
    // its own errors, so it cannot serve here).
    auto t = device_->create_texture(
        {.label = "one level", .format = TextureFormat::RGBA8, .width = 4, .height = 4});
    ASSERT_TRUE(t.ok()) << t.error().message;
    const std::vector<std::byte> texels(4 * 4 * 4);
    t->upload(texels, 2);
    EXPECT_EQ(device_->take_errors(), "GL_INVALID_OPERATION");
    EXPECT_EQ(device_->take_errors(), "") << "taking the errors clears them";
}

}  // namespace
}  // namespace puddle::gpu
