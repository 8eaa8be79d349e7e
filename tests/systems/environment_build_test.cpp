// The CPU half of a new environment (systems/sky/environment_build.hpp): the storage chosen for HDR and LDR
// skies, the face size asked for or picked and capped by the GPU, a panorama shrunk to what the GPU takes
// with the mip levels the GPU cannot make, the procedural sky's faces, and errors for a missing file or a
// stop. The GPU half: environment_system_test.cpp.
#include "systems/sky/environment_build.hpp"

#include <gtest/gtest.h>

#include <stop_token>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"

namespace puddle::test {
namespace {

using systems::EnvironmentRequest;
using systems::prepare_environment;

class EnvironmentBuildTest : public ::testing::Test {
protected:
    void SetUp() override {
        hdr_ = (dir_ / "sky.exr").string();
        write_float_image(hdr_, panorama_of(128, [](glm::vec3 d) { return glm::vec3(2.0f) + d; }));
        ldr_ = (dir_ / "sky.png").string();
        ASSERT_TRUE(assets::write_png(ldr_, assets::Image::make(128, 64)).ok());
    }
    EnvironmentRequest request(const std::string& image) const {
        return {.image = image,
                .max_cube_map_size = 2048,
                .max_texture_size = 2048,
                .half_float_render_targets = true};
    }
    TempDir dir_;
    std::string hdr_, ldr_;
};

// Half floats need half-float render targets for their mipmaps; without them HDR is RGBM in RGBA8.
TEST_F(EnvironmentBuildTest, HdrIsHalfFloatWhereTheGpuRendersItElseRgbmAndLdrIsSrgb) {
    auto half = prepare_environment(request(hdr_));
    ASSERT_TRUE(half.ok()) << half.error().message;
    EXPECT_TRUE(half->hdr);
    EXPECT_FALSE(half->rgbm);
    EXPECT_EQ(half->format, gpu::TextureFormat::RGBA16F);
    EnvironmentRequest no_half = request(hdr_);
    no_half.half_float_render_targets = false;
    auto rgbm = prepare_environment(no_half);
    ASSERT_TRUE(rgbm.ok()) << rgbm.error().message;
    EXPECT_TRUE(rgbm->rgbm);
    EXPECT_EQ(rgbm->format, gpu::TextureFormat::RGBA8);
    auto ldr = prepare_environment(request(ldr_));
    ASSERT_TRUE(ldr.ok()) << ldr.error().message;
    EXPECT_FALSE(ldr->hdr);
    EXPECT_FALSE(ldr->rgbm);
    EXPECT_EQ(ldr->format, gpu::TextureFormat::SRGB8_A8);
}

// A float panorama gets every mip level here, each half the one above; an 8-bit one only level 0 (the GPU
// makes the rest).
TEST_F(EnvironmentBuildTest, APanoramaKeepsItsMipChainForTheGpuToConvert) {
    auto hdr = prepare_environment(request(hdr_));
    ASSERT_TRUE(hdr.ok()) << hdr.error().message;
    EXPECT_TRUE(hdr->cube_levels.empty());
    ASSERT_GT(hdr->panorama_levels.size(), 1u);
    EXPECT_EQ(hdr->panorama_levels[0].width, 128);
    for (std::size_t level = 1; level < hdr->panorama_levels.size(); ++level)
        EXPECT_EQ(hdr->panorama_levels[level].width, std::max(1, 128 >> level)) << "level " << level;
    auto ldr = prepare_environment(request(ldr_));
    ASSERT_TRUE(ldr.ok()) << ldr.error().message;
    EXPECT_EQ(ldr->panorama_levels.size(), 1u);
}

TEST_F(EnvironmentBuildTest, TheFaceSizeIsAskedForOrPickedAndNeverPastTheGpu) {
    auto picked = prepare_environment(request(hdr_));
    ASSERT_TRUE(picked.ok());
    EXPECT_EQ(picked->face_size, render::auto_face_size(128, 2048));
    EnvironmentRequest asked = request(hdr_);
    asked.face_size = 20;
    EXPECT_EQ(prepare_environment(asked)->face_size, 20);
    asked.face_size = 64;
    asked.max_cube_map_size = 16;
    EXPECT_EQ(prepare_environment(asked)->face_size, 16);
}

// Fails if the panorama were uploaded at its own width on a GPU that takes less.
TEST_F(EnvironmentBuildTest, APanoramaWiderThanTheGpuTakesIsHalvedUntilItFits) {
    EnvironmentRequest small = request(hdr_);
    small.max_texture_size = 40;
    auto r = prepare_environment(small);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_FALSE(r->panorama_levels.empty());
    EXPECT_EQ(r->panorama_levels[0].width, 32);
    EXPECT_EQ(r->panorama_levels[0].height, 16);
}

TEST_F(EnvironmentBuildTest, TheProceduralSkyIsSixSquareFaces) {
    auto sky = prepare_environment(request(""));
    ASSERT_TRUE(sky.ok()) << sky.error().message;
    EXPECT_TRUE(sky->panorama_levels.empty());
    ASSERT_EQ(sky->cube_levels.size(), 1u) << "an sRGB cube: the GPU makes its mipmaps";
    for (const assets::Image& face : sky->cube_levels[0]) {
        EXPECT_EQ(face.width, sky->face_size);
        EXPECT_EQ(face.height, sky->face_size);
    }
    EXPECT_FALSE(sky->source.empty());
}

TEST_F(EnvironmentBuildTest, AMissingFileOrAStopIsAnAssetErrorNamingTheImage) {
    const std::string missing = (dir_ / "nope.exr").string();
    auto r = prepare_environment(request(missing));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ExitCode::Asset);
    EXPECT_NE(r.error().message.find(missing), std::string::npos) << r.error().message;
    std::stop_source stop;
    stop.request_stop();
    auto stopped = prepare_environment(request(hdr_), stop.get_token());
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().code, ExitCode::Asset);
    EXPECT_EQ(stopped.error().message,
              "environment: " + hdr_ + ": loading stopped (a newer one was asked for)");
}

}  // namespace
}  // namespace puddle::test
