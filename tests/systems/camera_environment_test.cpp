// The camera frame on the GPU (surfaceless EGL): YUV converted with the driver's matrix and range, the
// external-sampler path through an EGLImage, and the cube the puddle reflects.
#include "systems/sky/camera_environment.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <iterator>
#include <thread>

#include "camera/yuv_matrix.hpp"
#include "support/gated_worker_context.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::test {
namespace {

using camera::CameraImage;
using camera::PixelLayout;
using camera::YuvMatrix;
using systems::CameraEnvironment;

constexpr int tolerance = 3;  // of 255: 8-bit YUV codes of pure colours are rounded, and sRGB is re-encoded

struct Rgb {
    int r, g, b;
};

// Texel (x, y) of a read-back texture (GL rows: y = camera row, top first as uploaded).
Rgb texel(const std::vector<float>& t, int width, int x, int y) {
    const float* p = &t[(std::size_t(y) * width + x) * 4];
    return {int(std::lround(p[0] * 255)), int(std::lround(p[1] * 255)), int(std::lround(p[2] * 255))};
}

void expect_near(Rgb got, Rgb want, const std::string& what) {
    EXPECT_NEAR(got.r, want.r, tolerance) << what;
    EXPECT_NEAR(got.g, want.g, tolerance) << what;
    EXPECT_NEAR(got.b, want.b, tolerance) << what;
}

class CameraEnvironmentTest : public ::testing::Test {
protected:
    void SetUp() override {
        engine = make_engine(make_params({}), {64, 36});
        ASSERT_TRUE(engine);
        auto r = systems::build_camera_pipelines(engine->device(), env);
        ASSERT_TRUE(r) << r.error().message;
    }
    // Uploads and converts one frame, returns the colour texture.
    std::vector<float> convert(const CameraImage& image) {
        gpu::Device& device = engine->device();
        auto r = systems::upload_camera_frame(device, image, env);
        EXPECT_TRUE(r) << (r ? "" : r.error().message);
        systems::camera_environment_system(device, engine->params(), sky(), env);
        EXPECT_NE(env.frame, systems::CameraFrame::none);
        return device.read_texture(env.colour);
    }
    const systems::Environment& sky() { return engine->world().resource<systems::Environment>(); }
    std::unique_ptr<app::Engine> engine;
    CameraEnvironment env;
};

// A 16x9 RGBA camera frame of one orange, full range.
struct OrangeFrame {
    std::vector<std::uint8_t> bytes = [] {
        std::vector<std::uint8_t> b;
        for (int i = 0; i < 16 * 9; ++i) b.insert(b.end(), {240, 120, 20, 255});
        return b;
    }();
    CameraImage image{.layout = PixelLayout::Rgba,
                      .width = 16,
                      .height = 9,
                      .stride = 16 * 4,
                      .data = std::as_bytes(std::span(bytes)),
                      .full_range = true};
};

// The camera's five pipelines are built off the frame thread like a new look's (they were compiled on the
// frame thread at the first camera frame): while the worker is held, frames are taken and skipped and
// the puddle keeps the cubemap; once it builds, the next frame shows.
TEST(CameraEnvironmentPipelines, AreBuiltOffTheFrameThreadAndTheCubemapStaysMeanwhile) {
    auto engine = make_engine(make_params({}), {64, 36});
    ASSERT_TRUE(engine);
    auto context = engine->display().create_worker_context();
    ASSERT_TRUE(context) << context.error().message;
    auto gated = std::make_unique<GatedContext>(std::move(context).value());
    GatedContext& gate = *gated;
    engine->device().start_background_compiles(std::move(gated));
    const OrangeFrame orange;
    const CameraImage& image = orange.image;
    gpu::Device& device = engine->device();
    const auto& sky = engine->world().resource<systems::Environment>();
    CameraEnvironment env;
    for (int frame = 0; frame < 5; ++frame) {
        ASSERT_TRUE(systems::upload_camera_frame(device, image, env));
        systems::camera_environment_system(device, engine->params(), sky, env);
        EXPECT_EQ(env.reflection(), nullptr) << "frame " << frame << ": no pipeline is built yet";
    }
    gate.open();
    for (int frame = 0; frame < 2000 && !env.reflection(); ++frame) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        ASSERT_TRUE(systems::upload_camera_frame(device, image, env));
        systems::camera_environment_system(device, engine->params(), sky, env);
    }
    ASSERT_NE(env.reflection(), nullptr) << "the camera never showed once the worker built its pipelines";
    EXPECT_FALSE(env.failed());
}

TEST_F(CameraEnvironmentTest, YuyvLimitedBt709ConvertsToTheExpectedColours) {
    // Four pixel pairs: white, red, green, blue in BT.709 limited range; rows padded as drivers do.
    const std::array<std::array<int, 3>, 4> yuv{
        {{235, 128, 128}, {63, 102, 240}, {173, 42, 26}, {32, 240, 118}}};
    const std::array<Rgb, 4> rgb{{{255, 255, 255}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255}}};
    const int width = 8, height = 2, stride = width * 2 + 12;
    std::vector<std::byte> frame(std::size_t(stride) * height, std::byte{0x55});
    for (int y = 0; y < height; ++y)
        for (int pair = 0; pair < 4; ++pair) {
            auto* p = &frame[std::size_t(y) * stride + std::size_t(pair) * 4];
            p[0] = p[2] = std::byte(yuv[pair][0]);
            p[1] = std::byte(yuv[pair][1]);
            p[3] = std::byte(yuv[pair][2]);
        }
    const auto out = convert({.layout = PixelLayout::Yuyv,
                              .width = width,
                              .height = height,
                              .stride = stride,
                              .data = frame,
                              .matrix = YuvMatrix::Bt709,
                              .full_range = false});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            expect_near(texel(out, width, x, y), rgb[x / 2], fmt::format("pixel {},{}", x, y));
}

TEST_F(CameraEnvironmentTest, Nv12FullRangeBt601ConvertsToTheExpectedColours) {
    // 4x4 pixels, four 2x2 chroma blocks: red, green / blue, mid grey (JPEG-style full-range BT.601).
    const std::array<std::array<int, 3>, 4> yuv{
        {{76, 85, 255}, {150, 44, 21}, {29, 255, 107}, {128, 128, 128}}};
    const std::array<Rgb, 4> rgb{{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {128, 128, 128}}};
    const int width = 4, height = 4, stride = 8;
    std::vector<std::byte> frame(std::size_t(stride) * height * 3 / 2, std::byte{0x55});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            frame[std::size_t(y) * stride + x] = std::byte(yuv[(y / 2) * 2 + x / 2][0]);
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 2; ++bx) {
            auto* uv = &frame[std::size_t(stride) * height + std::size_t(by) * stride + std::size_t(bx) * 2];
            uv[0] = std::byte(yuv[by * 2 + bx][1]);
            uv[1] = std::byte(yuv[by * 2 + bx][2]);
        }
    const auto out = convert({.layout = PixelLayout::Nv12,
                              .width = width,
                              .height = height,
                              .stride = stride,
                              .data = frame,
                              .matrix = YuvMatrix::Bt601,
                              .full_range = true});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            expect_near(texel(out, width, x, y), rgb[(y / 2) * 2 + x / 2], fmt::format("pixel {},{}", x, y));
}

TEST_F(CameraEnvironmentTest, TheRangeMatters) {
    // The same codes read as full range come out darker at white and lighter at black.
    const int width = 2, height = 1, stride = 4;
    std::vector<std::byte> white{std::byte{235}, std::byte{128}, std::byte{235}, std::byte{128}};
    const auto limited = convert({.layout = PixelLayout::Yuyv,
                                  .width = width,
                                  .height = height,
                                  .stride = stride,
                                  .data = white,
                                  .full_range = false});
    const auto full = convert({.layout = PixelLayout::Yuyv,
                               .width = width,
                               .height = height,
                               .stride = stride,
                               .data = white,
                               .full_range = true});
    EXPECT_NEAR(texel(limited, width, 0, 0).g, 255, tolerance);
    EXPECT_NEAR(texel(full, width, 0, 0).g, 235, tolerance);
}

TEST_F(CameraEnvironmentTest, ExternalSamplerPathMatchesTheSource) {
    if (!env.support.external_sampler || !env.support.texture_images)
        GTEST_SKIP() << "needs GL_OES_EGL_image_external_essl3 and EGL_KHR_gl_texture_2D_image";
    if (env.support.dmabuf_import)
        std::printf("note: this EGL also imports dmabufs (zero-copy camera path available)\n");
    gpu::Device& device = engine->device();
    // Where dmabuf import is missing, an EGLImage made from a GL texture drives the same sampler path.
    const int width = 4, height = 2;
    const std::array<Rgb, 8> colours{{{255, 0, 0},
                                      {0, 255, 0},
                                      {0, 0, 255},
                                      {255, 255, 255},
                                      {10, 20, 30},
                                      {128, 64, 32},
                                      {0, 0, 0},
                                      {200, 180, 90}}};
    std::vector<std::uint8_t> rgba;
    for (const Rgb& c : colours)
        rgba.insert(rgba.end(), {std::uint8_t(c.r), std::uint8_t(c.g), std::uint8_t(c.b), 255});
    gpu::Texture source =
        device.create_texture({.label = "test source", .width = width, .height = height}).value();
    source.upload(std::as_bytes(std::span(rgba)));
    auto image = device.create_external_image({.label = "test image", .source = &source});
    ASSERT_TRUE(image) << image.error().message;
    env.colour = device
                     .create_texture({.label = "camera colour",
                                      .format = gpu::TextureFormat::SRGB8_A8,
                                      .width = width,
                                      .height = height,
                                      .mip_levels = 3})
                     .value();
    env.pending_import = &*image;
    env.frame = systems::CameraFrame::uploaded;
    systems::camera_environment_system(device, engine->params(), sky(), env);
    const auto out = device.read_texture(env.colour);
    for (int i = 0; i < width * height; ++i)
        expect_near(texel(out, width, i % width, i / width), colours[std::size_t(i)],
                    fmt::format("texel {}", i));
}

TEST_F(CameraEnvironmentTest, BlendMixesTheCameraWithTheCubemap) {
    gpu::Device& device = engine->device();
    const OrangeFrame orange;
    const CameraImage& image = orange.image;
    auto face_mean = [&](const char* blend, int face) {
        engine->params().set(params::ParamId::environment_camera_blend, std::stof(blend),
                             params::ParamSource::CommandLine);
        EXPECT_TRUE(systems::upload_camera_frame(device, image, env));
        systems::camera_environment_system(device, engine->params(), sky(), env);
        const auto t = device.read_texture(env.cube, face);
        std::array<double, 3> mean{};
        for (std::size_t i = 0; i < t.size(); i += 4)
            for (std::size_t c = 0; c < 3; ++c) mean[c] += t[i + c] * 255.0 / (t.size() / 4);
        return mean;
    };
    for (int face : {0, 3}) {
        const auto camera_only = face_mean("1", face);
        EXPECT_NEAR(camera_only[0], 240, tolerance) << "face " << face;
        EXPECT_NEAR(camera_only[1], 120, tolerance) << "face " << face;
        EXPECT_NEAR(camera_only[2], 20, tolerance) << "face " << face;
        const auto sky_only = face_mean("0", face);
        EXPECT_LT(sky_only[0], 100) << "the night sky is dark, face " << face;
        const auto half = face_mean("0.5", face);
        EXPECT_GT(half[0], sky_only[0] + 40);
        EXPECT_LT(half[0], camera_only[0] - 20);
    }
}

// The cube is at most 256 per face and no sharper than the sky: a slow board's 64-texel sky gets a 64-texel
// camera cube, which still shows the camera.
TEST_F(CameraEnvironmentTest, TheCubeIsNoSharperThanTheSky) {
    const OrangeFrame orange;
    ASSERT_TRUE(systems::upload_camera_frame(engine->device(), orange.image, env));
    systems::camera_environment_system(engine->device(), engine->params(), sky(), env);
    ASSERT_GT(sky().cube.width(), 256);
    EXPECT_EQ(env.cube.width(), 256);

    auto small = make_engine(make_params({"environment.face_size=64"}), {64, 36});
    ASSERT_TRUE(small);
    CameraEnvironment small_env;
    ASSERT_TRUE(systems::build_camera_pipelines(small->device(), small_env));
    small->params().set(params::ParamId::environment_camera_blend, 1.0f, params::ParamSource::CommandLine);
    ASSERT_TRUE(systems::upload_camera_frame(small->device(), orange.image, small_env));
    const auto& small_sky = small->world().resource<systems::Environment>();
    systems::camera_environment_system(small->device(), small->params(), small_sky, small_env);
    ASSERT_EQ(small_sky.cube.width(), 64);
    EXPECT_EQ(small_env.cube.width(), 64);
    ASSERT_EQ(small_env.reflection(), &small_env.cube);
    const auto face = small->device().read_texture(small_env.cube, 0);
    ASSERT_EQ(face.size(), std::size_t{64 * 64 * 4});
    std::array<double, 3> mean{};
    for (std::size_t i = 0; i < face.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) mean[c] += face[i + c] * 255.0 / (64 * 64);
    expect_near({int(std::lround(mean[0])), int(std::lround(mean[1])), int(std::lround(mean[2]))},
                {240, 120, 20}, "the 64-texel cube shows the camera");
}

// What the conversion shader should give for one sample, worked out on the CPU: the driver's matrix and
// range (yuv_matrix), clamped, in sRGB codes as the colour texture stores them.
Rgb reference(int y, int u, int v, YuvMatrix matrix, bool full_range) {
    const camera::YuvToRgb m = camera::yuv_to_rgb(matrix, full_range);
    const glm::vec3 c = glm::clamp(m.matrix * (glm::vec3(y, u, v) / 255.0f - m.offset), 0.0f, 1.0f);
    return {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255))};
}

std::vector<std::byte> read_case(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
    return std::vector<std::byte>(reinterpret_cast<const std::byte*>(chars.data()),
                                  reinterpret_cast<const std::byte*>(chars.data()) + chars.size());
}

TEST_F(CameraEnvironmentTest, OddWidthNv12MatchesTheEvenReference) {
    const std::filesystem::path cases = std::filesystem::path(PUDDLE_SHARED_DIR) / "cases" / "camera";
    if (!std::filesystem::exists(cases / "nv12_65x48_stride80.raw"))
        GTEST_SKIP() << "needs " << cases.string() << " (the shared cases folder beside the source tree)";
    const auto odd_bytes = read_case(cases / "nv12_65x48_stride80.raw");
    const auto even_bytes = read_case(cases / "nv12_64x48_stride64.raw");
    ASSERT_EQ(odd_bytes.size(), 80u * (48 + 24));
    ASSERT_EQ(even_bytes.size(), 64u * (48 + 24));
    const auto even =
        convert({.layout = PixelLayout::Nv12, .width = 64, .height = 48, .stride = 64, .data = even_bytes});
    const auto odd =
        convert({.layout = PixelLayout::Nv12, .width = 65, .height = 48, .stride = 80, .data = odd_bytes});
    ASSERT_EQ(odd.size(), 65u * 48 * 4);
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x)
            expect_near(texel(odd, 65, x, y), texel(even, 64, x, y), fmt::format("pixel {},{}", x, y));
        // The 65th column takes the 33rd chroma pair (bytes 64 and 65 of its chroma row), not green.
        const auto at = [&](std::size_t i) { return std::to_integer<int>(odd_bytes[i]); };
        const std::size_t chroma = 80u * 48 + 80u * std::size_t(y / 2) + 64;
        expect_near(
            texel(odd, 65, 64, y),
            reference(at(80u * std::size_t(y) + 64), at(chroma), at(chroma + 1), YuvMatrix::Bt601, false),
            fmt::format("edge pixel 64,{}", y));
    }
}

TEST_F(CameraEnvironmentTest, OddWidthsAndHeightsReachTheLastChromaSample) {
    // NV12 5x3, bytesperline 8: chroma 3 pairs by 2 rows, each block its own colour; every pixel checked.
    const int width = 5, height = 3, stride = 8;
    std::vector<std::byte> nv12(std::size_t(stride) * (height + 2), std::byte{0x55});
    const auto luma = [](int x, int y) { return 60 + 30 * x + 10 * y; };
    const auto cb = [](int bx, int by) { return 40 + 70 * bx + 20 * by; };
    const auto cr = [](int bx, int by) { return 220 - 60 * bx - 30 * by; };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) nv12[std::size_t(y) * stride + x] = std::byte(luma(x, y));
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 3; ++bx) {
            nv12[std::size_t(stride) * (height + by) + std::size_t(bx) * 2] = std::byte(cb(bx, by));
            nv12[std::size_t(stride) * (height + by) + std::size_t(bx) * 2 + 1] = std::byte(cr(bx, by));
        }
    const auto out = convert(
        {.layout = PixelLayout::Nv12, .width = width, .height = height, .stride = stride, .data = nv12});
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            expect_near(texel(out, width, x, y),
                        reference(luma(x, y), cb(x / 2, y / 2), cr(x / 2, y / 2), YuvMatrix::Bt601, false),
                        fmt::format("NV12 pixel {},{}", x, y));

    // YUYV 5x2: the fifth pixel is Y0 of a third pair whose Y1 is padding.
    const int yuyv_stride = 16;
    std::vector<std::byte> yuyv(std::size_t(yuyv_stride) * 2, std::byte{0x55});
    for (int y = 0; y < 2; ++y)
        for (int pair = 0; pair < 3; ++pair) {
            auto* p = &yuyv[std::size_t(y) * yuyv_stride + std::size_t(pair) * 4];
            p[0] = std::byte(luma(2 * pair, y));
            p[1] = std::byte(cb(pair, y));
            p[2] = std::byte(luma(2 * pair + 1, y));
            p[3] = std::byte(cr(pair, y));
        }
    const auto packed = convert(
        {.layout = PixelLayout::Yuyv, .width = width, .height = 2, .stride = yuyv_stride, .data = yuyv});
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < width; ++x)
            expect_near(texel(packed, width, x, y),
                        reference(luma(x, y), cb(x / 2, y), cr(x / 2, y), YuvMatrix::Bt601, false),
                        fmt::format("YUYV pixel {},{}", x, y));
}

TEST_F(CameraEnvironmentTest, AFrameTooShortForItsFormatIsNotUploaded) {
    const std::vector<std::byte> grey(8 * 4 + 8 * 2, std::byte{128});
    (void)convert({.layout = PixelLayout::Nv12, .width = 8, .height = 4, .stride = 8, .data = grey});
    // The same size with one chroma row missing: refused, and the colour texture keeps its picture.
    const auto before = engine->device().read_texture(env.colour);
    std::vector<std::byte> dark(8 * 4 + 8 * 2 - 1, std::byte{16});
    auto r = systems::upload_camera_frame(
        engine->device(), {.layout = PixelLayout::Nv12, .width = 8, .height = 4, .stride = 8, .data = dark},
        env);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "camera: frame not uploaded: NV12 8x4 in 47 bytes, needs 48");
    systems::camera_environment_system(engine->device(), engine->params(), sky(), env);
    EXPECT_EQ(engine->device().read_texture(env.colour), before);
}

}  // namespace
}  // namespace puddle::test
