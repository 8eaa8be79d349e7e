// A panorama becomes a cube map (render/equirect_to_cube.hpp) whose faces look where GL says they look, in
// half floats or, where half-float targets are missing (forced here), RGBM-style RGBA8; converted in bands
// of rows over many steps it gives the same texels as whole faces.
#include "render/equirect_to_cube.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "assets/rgbm.hpp"
#include "support/gpu_fixture.hpp"
#include "systems/environment_test_support.hpp"

namespace puddle::test {
namespace {

// HDR colours, one per axis in GL face order (+X, -X, +Y, -Y, +Z, -Z).
const std::array<glm::vec3, 6> kAxisColours{{{4.0f, 0.1f, 0.1f},
                                             {0.1f, 2.0f, 0.1f},
                                             {0.1f, 0.1f, 8.0f},
                                             {0.5f, 0.5f, 0.05f},
                                             {0.05f, 1.5f, 1.5f},
                                             {3.0f, 0.05f, 3.0f}}};

std::size_t dominant_axis(glm::vec3 d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x > 0 ? 0 : 1;
    if (a.y >= a.z) return d.y > 0 ? 2 : 3;
    return d.z > 0 ? 4 : 5;
}

// Where GL samples face `face` at (s, t): the major-axis table of the GLES 3.0 specification, inverted.
glm::vec3 face_direction(int face, float s, float t) {
    const float sc = 2 * s - 1, tc = 2 * t - 1;
    switch (face) {
        case 0:
            return {1, -tc, -sc};
        case 1:
            return {-1, -tc, sc};
        case 2:
            return {sc, 1, tc};
        case 3:
            return {sc, -1, -tc};
        case 4:
            return {sc, -tc, 1};
        default:
            return {-sc, -tc, -1};
    }
}

// Texel (x, row) of a cube face read back from the GPU, as linear radiance whatever the storage.
glm::vec3 cube_texel(const std::vector<float>& face, int size, int x, int row, bool rgbm) {
    const float* p = face.data() + (std::size_t(row) * size + x) * 4;
    if (!rgbm) return {p[0], p[1], p[2]};
    std::array<std::uint8_t, 4> bytes{};
    for (int c = 0; c < 4; ++c) bytes[c] = static_cast<std::uint8_t>(std::lround(p[c] * 255.0f));
    const auto v = assets::decode_rgbm(bytes.data());
    return {v[0], v[1], v[2]};
}

// RGBM shares one scale: each channel is exact to a fraction of the brightest one.
void expect_near_relative(glm::vec3 got, glm::vec3 want, float tolerance, const std::string& what) {
    const float brightest = std::max({want.r, want.g, want.b});
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], tolerance * brightest) << what << " channel " << c;
}

class EquirectToCube : public ::testing::TestWithParam<bool> {};  // true: forced RGBM fallback

TEST_P(EquirectToCube, SixDirectionsOfSixColoursGiveFaceCentresOfThoseColours) {
    const bool forced_fallback = GetParam();
    auto engine = make_engine(make_params({}), {32, 32}, {.forbid_float_targets = forced_fallback});
    ASSERT_TRUE(engine);
    gpu::Device& device = engine->device();
    ASSERT_EQ(device.caps().half_float_render_targets, !forced_fallback);
    const assets::Image panorama =
        panorama_of(256, [](glm::vec3 d) { return kAxisColours[dominant_axis(d)]; });

    const auto format = forced_fallback ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::RGBA16F;
    auto cube = render::equirect_to_cube(device, panorama, 32, format, forced_fallback, 32);
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    for (int face = 0; face < 6; ++face) {
        const auto texels = device.read_texture(*cube, face);
        const glm::vec3 centre = cube_texel(texels, 32, 16, 16, forced_fallback);
        expect_near_relative(centre, kAxisColours[std::size_t(face)], 0.02f,
                             std::string("face ") + assets::cube_face_names[std::size_t(face)]);
    }
}

TEST_P(EquirectToCube, EveryTexelHoldsThePanoramaInTheDirectionGlSamplesIt) {
    const bool forced_fallback = GetParam();
    auto engine = make_engine(make_params({}), {32, 32}, {.forbid_float_targets = forced_fallback});
    ASSERT_TRUE(engine);
    gpu::Device& device = engine->device();
    // A smooth function of direction, so any turn or mirror of a face shows as a wrong colour.
    auto radiance = [](glm::vec3 d) { return 0.5f + 0.5f * d; };
    const int size = 16;
    const auto format = forced_fallback ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::RGBA16F;
    auto cube =
        render::equirect_to_cube(device, panorama_of(512, radiance), size, format, forced_fallback, size);
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    for (int face = 0; face < 6; ++face) {
        const auto texels = device.read_texture(*cube, face);
        for (int row = 0; row < size; ++row)
            for (int x = 0; x < size; ++x) {
                const glm::vec3 want =
                    radiance(glm::normalize(face_direction(face, (x + 0.5f) / size, (row + 0.5f) / size)));
                const glm::vec3 got = cube_texel(texels, size, x, row, forced_fallback);
                ASSERT_LT(glm::length(got - want), 0.03f)
                    << assets::cube_face_names[std::size_t(face)] << " texel " << x << "," << row;
            }
    }
}

TEST_P(EquirectToCube, BandsOfRowsOverManyStepsGiveTheSameCubeAsWholeFaces) {
    // A live reload converts a few rows a frame (scissored passes); the cube must be the same texels.
    const bool forced_fallback = GetParam();
    auto engine = make_engine(make_params({}), {32, 32}, {.forbid_float_targets = forced_fallback});
    ASSERT_TRUE(engine);
    gpu::Device& device = engine->device();
    const assets::Image panorama = panorama_of(256, [](glm::vec3 d) { return 0.5f + 0.5f * d; });
    const auto format = forced_fallback ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::RGBA16F;
    const int size = 16;
    auto whole = render::equirect_to_cube(device, panorama, size, format, forced_fallback, size);
    ASSERT_TRUE(whole.ok()) << whole.error().message;
    render::EquirectToCube banded(render::panorama_mip_chain(panorama, device.caps().max_texture_size), size,
                                  format, forced_fallback, size);
    render::EquirectPipelines pipelines;
    int steps = 0;
    for (bool done = false; !done; ++steps) {
        auto r = banded.step(device, 3 * size, pipelines);  // three rows of a level-0 face, one panorama row
        ASSERT_TRUE(r.ok()) << r.error().message;
        done = *r;
        std::this_thread::yield();  // the pipeline builds on the compiler's thread meanwhile
        ASSERT_LT(steps, 1'000'000) << "the conversion never ends";
    }
    EXPECT_GT(steps, 6 * 5) << "each level-0 face alone takes six bands";
    const gpu::Texture cube = banded.take_cube();
    for (int face = 0; face < 6; ++face)
        EXPECT_EQ(device.read_texture(cube, face), device.read_texture(*whole, face))
            << assets::cube_face_names[std::size_t(face)];
}

INSTANTIATE_TEST_SUITE_P(HalfFloatAndRgbm, EquirectToCube, ::testing::Values(false, true),
                         [](const auto& test_case) {
                             return test_case.param ? "ForcedRgbmFallback" : "HalfFloat";
                         });

}  // namespace
}  // namespace puddle::test
