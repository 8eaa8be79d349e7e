// The environment on the GPU: the face size and storage chosen for a sky, the forced RGBM fallback showing
// the same sky, the real files of ../shared/assets loading and rendering, and changed images reloading at
// run time while a bad one keeps what is shown. The panorama-to-cube conversion: equirect_to_cube_test.cpp.
#include "systems/sky/environment_system.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <thread>

#include "assets/image_io.hpp"
#include "assets/rgbm.hpp"
#include "params/config_loader.hpp"
#include "render/equirect_to_cube.hpp"
#include "support/gpu_fixture.hpp"
#include "support/log_lines.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"
#include "systems/render_test_support.hpp"

namespace puddle::test {
namespace {

using params::ParamId;
using params::ParamSource;

// Live reloads read files on a worker thread and finish over several frames: renders until they have,
// then one more frame, which shows the result.
assets::Image render_until_reloaded(app::Engine& engine) {
    (void)render_frames(engine, 1);  // the reload system sees the change
    const auto& reload = engine.world().resource<systems::EnvironmentReload>();
    for (int i = 0; i < 60000 && reload.pending(); ++i) {
        (void)render_frames(engine, 1);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_FALSE(reload.pending()) << "a reload still going after a minute";
    return render_frames(engine, 1);
}

TEST(EnvironmentSystem, FaceSizeIsAQuarterOfThePanoramaUnlessSet) {
    EXPECT_EQ(render::auto_face_size(1024, 16384), 256);
    EXPECT_EQ(render::auto_face_size(8192, 16384), 1024) << "capped: a Pi has little memory";
    EXPECT_EQ(render::auto_face_size(8192, 512), 512) << "never past the GPU's limit";

    TempDir dir;
    const std::string path = (dir / "sky.exr").string();
    write_float_image(path, panorama_of(128, [](glm::vec3) { return glm::vec3(2.0f); }));
    auto automatic = make_engine(make_params({"environment.image=" + path}), {32, 32});
    ASSERT_TRUE(automatic);
    EXPECT_EQ(automatic->world().resource<systems::Environment>().cube.width(), 32);
    EXPECT_TRUE(automatic->world().resource<systems::Environment>().hdr);
    auto chosen =
        make_engine(make_params({"environment.image=" + path, "environment.face_size=20"}), {32, 32});
    ASSERT_TRUE(chosen);
    EXPECT_EQ(chosen->world().resource<systems::Environment>().cube.width(), 20);
}

TEST(EnvironmentSystem, HdrPicksHalfFloatOrForcedRgbmAndLdrStaysSrgb) {
    TempDir dir;
    const std::string hdr = (dir / "sky.hdr").string();
    write_float_image(hdr, panorama_of(64, [](glm::vec3) { return glm::vec3(3.0f); }));
    auto half = make_engine(make_params({"environment.image=" + hdr}), {32, 32});
    ASSERT_TRUE(half);
    EXPECT_EQ(half->world().resource<systems::Environment>().cube.desc().format, gpu::TextureFormat::RGBA16F);
    EXPECT_FALSE(half->world().resource<systems::Environment>().rgbm);
    auto fallback =
        make_engine(make_params({"environment.image=" + hdr}), {32, 32}, {.forbid_float_targets = true});
    ASSERT_TRUE(fallback);
    EXPECT_EQ(fallback->world().resource<systems::Environment>().cube.desc().format,
              gpu::TextureFormat::RGBA8);
    EXPECT_TRUE(fallback->world().resource<systems::Environment>().rgbm);
    const std::string png = (dir / "sky.png").string();
    ASSERT_TRUE(
        assets::write_png(png, assets::to_srgb8(panorama_of(64, [](glm::vec3) { return glm::vec3(0.5f); })))
            .ok());
    auto ldr = make_engine(make_params({"environment.image=" + png}), {32, 32});
    ASSERT_TRUE(ldr);
    EXPECT_EQ(ldr->world().resource<systems::Environment>().cube.desc().format, gpu::TextureFormat::SRGB8_A8);
    // The procedural night sky is HDR (its windows and moon are brighter than white): half floats here.
    auto procedural = make_engine(make_params({}), {32, 32});
    ASSERT_TRUE(procedural);
    EXPECT_TRUE(procedural->world().resource<systems::Environment>().hdr);
    EXPECT_EQ(procedural->world().resource<systems::Environment>().cube.desc().format,
              gpu::TextureFormat::RGBA16F);
}

// The top rows of a picture: the sky seen directly, above the puddle.
assets::Image top_rows(const assets::Image& img, int rows) {
    assets::Image out = assets::Image::make(img.width, rows);
    std::copy(img.data.begin(), img.data.begin() + std::ptrdiff_t(out.data.size()), out.data.begin());
    return out;
}

TEST(EnvironmentSystem, ForcedRgbmFallbackShowsTheSameSky) {
    TempDir dir;
    const std::string path = (dir / "sky.exr").string();
    // Filtering between a lit texel and a dark one gives RGBM less than their average (rgbm.hpp), so the
    // lights' edges differ by a few levels: a looser bound than the goldens', and the lights stay white.
    write_float_image(path, city_lights_panorama(1024));
    const params::Params p =
        make_params({"environment.image=" + path, "rain.intensity=0", "wave.resolution=128",
                     "camera.position=0,14,30", "camera.target=0,9,0"});
    auto half = make_engine(p, {160, 90});
    auto rgbm = make_engine(p, {160, 90}, {.forbid_float_targets = true});
    ASSERT_TRUE(half && rgbm);
    // Only the sky seen directly: forcing the fallback also gives the water an 8-bit surface, whose
    // slopes differ slightly (its own test covers that).
    const assets::Image a = top_rows(render_frames(*half, 3), 36), b = top_rows(render_frames(*rgbm, 3), 36);
    const ImageDiff d = compare_images(a, b, 24);
    if (d.mean_abs_diff >= 5.0) {
        (void)assets::write_png((output_dir() / "rgbm_fallback.half.png").string(), a);
        (void)assets::write_png((output_dir() / "rgbm_fallback.rgbm.png").string(), b);
    }
    EXPECT_LT(d.mean_abs_diff, 5.0);
    EXPECT_LT(d.fraction_over, 0.12);
    EXPECT_GT(luma_stddev(a, 0, 0, 160, 36), 20.0) << "lit windows against a dark sky, not a flat fill";
    auto brightest = [](const assets::Image& img) {
        int m = 0;
        for (std::size_t i = 0; i < img.data.size(); i += 4) m = std::max<int>(m, img.data[i + 1]);
        return m;
    };
    EXPECT_GE(brightest(b), 250) << "HDR windows stay white through RGBM";
    EXPECT_GE(brightest(a), 250);
}

TEST(EnvironmentSystem, ChangedImagesReloadAndBadOnesKeepThePicture) {
    TempDir dir;
    assets::Image red = assets::Image::make(8, 8);
    for (std::size_t i = 0; i < red.data.size(); i += 4) red.data[i] = 255, red.data[i + 3] = 255;
    const std::string cross = (dir / "cross.png").string();
    ASSERT_TRUE(assets::write_png(cross,
                                  [] {
                                      assets::Image c = assets::Image::make(32, 24);
                                      std::fill(c.data.begin(), c.data.end(), std::uint8_t{200});
                                      return c;
                                  }())
                    .ok());
    const std::string ground = (dir / "red.png").string();
    ASSERT_TRUE(assets::write_png(ground, red).ok());

    auto engine = make_engine(make_params({"rain.intensity=0", "overlay.rain=false",
                                           "environment.cloud_drift=0", "ground.checkerboard=false"}),
                              {96, 54});
    ASSERT_TRUE(engine);
    const assets::Image before = render_frames(*engine, 2);
    auto& params = engine->params();
    auto set = [&](ParamId id, params::ParamValue v) { params.set(id, std::move(v), ParamSource::Knob); };

    set(ParamId::environment_image, std::string("/nonexistent/sky.hdr"));
    set(ParamId::ground_image, (dir / "missing.jpg").string());
    const assets::Image kept = render_until_reloaded(*engine);
    EXPECT_EQ(compare_images(before, kept, 0).max_channel_diff, 0) << "a failed reload changes nothing";
    EXPECT_EQ(engine->world().resource<systems::Environment>().source, "procedural night sky");
    EXPECT_EQ(engine->world().resource<systems::Ground>().source, "procedural setts (drawn by the shader)");

    set(ParamId::environment_image, cross);
    set(ParamId::ground_image, ground);
    const assets::Image changed = render_until_reloaded(*engine);
    EXPECT_EQ(engine->world().resource<systems::Environment>().source, cross);
    EXPECT_EQ(engine->world().resource<systems::Ground>().source, ground);
    EXPECT_GT(compare_images(before, changed, 8).mean_abs_diff, 10.0);

    const std::string pano = (dir / "pano.exr").string();
    write_float_image(pano, panorama_of(64, [](glm::vec3) { return glm::vec3(1.0f); }));
    set(ParamId::environment_image, pano);
    set(ParamId::environment_face_size, 12);
    (void)render_until_reloaded(*engine);
    EXPECT_EQ(engine->world().resource<systems::Environment>().cube.width(), 12);
}

// The checkerboard and the setts are drawn by the shader: no ground texture is made for either. A
// ground.image asked for under the checkerboard is read only when the checkerboard turns off; the setts show
// until it is ready (here: for good, the file is missing), and taking the image away shows them again.
TEST(EnvironmentSystem, TheGroundImageIsReadOnlyWhenItShows) {
    TempDir dir;
    assets::Image red = assets::Image::make(8, 8);
    for (std::size_t i = 0; i < red.data.size(); i += 4) red.data[i] = 255, red.data[i + 3] = 255;
    const std::string red_path = (dir / "red.png").string();
    ASSERT_TRUE(assets::write_png(red_path, red).ok());

    auto engine =
        make_engine(make_params({"rain.intensity=0", "overlay.rain=false", "environment.cloud_drift=0",
                                 "water.turbidity=0.05", "ground.checkerboard=true"}),
                    {96, 54});
    ASSERT_TRUE(engine);
    const auto& ground = engine->world().resource<systems::Ground>();
    EXPECT_FALSE(ground.made);
    EXPECT_FALSE(ground.requested_image.has_value());
    EXPECT_EQ(ground.source, "checkerboard");
    const assets::Image checkerboard = render_frames(*engine, 2);

    auto setts_engine = make_engine(make_params({"rain.intensity=0", "overlay.rain=false",
                                                 "environment.cloud_drift=0", "water.turbidity=0.05"}),
                                    {96, 54});
    ASSERT_TRUE(setts_engine);
    EXPECT_FALSE(setts_engine->world().resource<systems::Ground>().made) << "the setts need no texture";
    const assets::Image setts = render_frames(*setts_engine, 2);
    EXPECT_GT(compare_images(checkerboard, setts, 8).mean_abs_diff, 2.0);

    auto& params = engine->params();
    // As --set: make_params set the checkerboard at that precedence.
    auto set = [&](ParamId id, params::ParamValue v) {
        ASSERT_TRUE(params.set(id, std::move(v), ParamSource::CommandLine));
    };
    test::LogLines errors(spdlog::level::err);
    set(ParamId::ground_image, std::string("/nonexistent/stones.jpg"));
    (void)render_until_reloaded(*engine);
    EXPECT_FALSE(ground.requested_image.has_value()) << "not read while the checkerboard shows";
    EXPECT_EQ(errors.count("ground"), 0);

    set(ParamId::ground_checkerboard, false);
    const assets::Image missing = render_until_reloaded(*engine);
    EXPECT_EQ(errors.count("/nonexistent/stones.jpg"), 1);
    EXPECT_EQ(errors.count("(keeping the procedural setts)"), 1);
    EXPECT_FALSE(ground.made);
    EXPECT_LE(compare_images(setts, missing, 1).max_channel_diff, 1) << "a bad image keeps the setts";

    set(ParamId::ground_image, red_path);
    const assets::Image red_ground = render_until_reloaded(*engine);
    EXPECT_TRUE(ground.made);
    EXPECT_EQ(ground.source, red_path);
    EXPECT_GT(compare_images(setts, red_ground, 8).mean_abs_diff, 2.0);

    set(ParamId::ground_image, std::string());
    const assets::Image back = render_until_reloaded(*engine);
    EXPECT_FALSE(ground.made) << "the image taken away is freed";
    EXPECT_FALSE(ground.requested_image.has_value());
    EXPECT_LE(compare_images(setts, back, 1).max_channel_diff, 1);
    EXPECT_EQ(errors.count("keeping"), 1) << "no error since the missing file's";
}

// A ground image is at most 2048 a side (halved on the worker: the upload and mipmaps run on the frame
// thread), the log says so, and an error names the parameter and the file.
TEST(EnvironmentSystem, AGroundImageIsHalvedToTheGroundsLimitAndErrorsNameTheParameter) {
    TempDir dir;
    const std::string wide = (dir / "wide.png").string();
    ASSERT_TRUE(assets::write_png(wide, assets::Image::make(8192, 2)).ok());
    auto prepared = systems::prepare_ground(wide, 16384);
    ASSERT_TRUE(prepared) << prepared.error().message;
    EXPECT_EQ(prepared->image.width, systems::ground_max_size);
    EXPECT_EQ(prepared->source, wide + " (2048x1, halved from 8192x2)");
    auto small_gpu = systems::prepare_ground(wide, 1024);
    ASSERT_TRUE(small_gpu);
    EXPECT_EQ(small_gpu->image.width, 1024) << "and never past the GPU's limit";

    auto missing = systems::prepare_ground((dir / "missing.png").string(), 16384);
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.error().message.starts_with("ground.image: ")) << missing.error().message;
    EXPECT_NE(missing.error().message.find("missing.png"), std::string::npos);
    EXPECT_EQ(missing.error().code, ExitCode::Asset);
}

// A panorama reloaded at run time is converted with the shader the first one compiled (the pipeline stays in
// the Environment resource): a sky edit compiles nothing on the frame thread. Program names only grow on
// Mesa, so a program compiled again would have a new one.
TEST(EnvironmentSystem, ASecondPanoramaIsConvertedWithoutCompilingAgain) {
    TempDir dir;
    const std::string first = (dir / "first.exr").string(), second = (dir / "second.exr").string();
    write_float_image(first, panorama_of(64, [](glm::vec3) { return glm::vec3(1.0f); }));
    write_float_image(second, panorama_of(64, [](glm::vec3) { return glm::vec3(0.25f, 0.5f, 2.0f); }));
    auto engine = make_engine(make_params({"environment.image=" + first}), {32, 32});
    ASSERT_TRUE(engine);
    const auto& env = engine->world().resource<systems::Environment>();
    const auto encoding = env.rgbm ? render::CubeEncoding::rgbm : render::CubeEncoding::plain;
    const render::BuiltPipeline* converted = env.panorama_pipelines.find(encoding);
    ASSERT_NE(converted, nullptr) << "the start-up conversion keeps its pipeline";
    const unsigned program = converted->pipeline.id();

    ASSERT_TRUE(engine->params().set(ParamId::environment_image, second, ParamSource::CommandLine));
    (void)render_until_reloaded(*engine);
    ASSERT_EQ(env.source, second);
    ASSERT_NE(env.panorama_pipelines.find(encoding), nullptr);
    EXPECT_EQ(env.panorama_pipelines.find(encoding)->pipeline.id(), program);
}

// ../shared/assets: the Poly Haven HDRI, the cube folder, the paving photo and a 16-bit PNG render.
TEST(EnvironmentSystemShared, RealFilesLoadAndRender) {
    const std::string assets = shared_assets_dir();
    if (assets.empty()) GTEST_SKIP() << "../shared/assets not found: the real-file tests need it";
    const assets::Image plain = render_with({"rain.intensity=0"}, 3);
    const std::array<std::initializer_list<std::string>, 3> cases{{
        {"rain.intensity=0", "environment.image=" + assets + "/env.hdr", "ground.checkerboard=false",
         "ground.image=" + assets + "/pavement.jpg"},
        {"rain.intensity=0", "environment.image=" + assets + "/cubemap"},
        {"rain.intensity=0", "ground.checkerboard=false", "ground.image=" + assets + "/extra/rgb16.png",
         "water.turbidity=0"},
    }};
    for (const auto& sets : cases) {
        const assets::Image img = render_with(sets, 3);
        ASSERT_FALSE(img.empty());
        EXPECT_GT(luma_stddev(img, 0, 0, img.width, img.height), 5.0) << sets.begin()[1];
        EXPECT_GT(compare_images(plain, img, 8).mean_abs_diff, 3.0) << "the file shows";
    }
}

}  // namespace
}  // namespace puddle::test
