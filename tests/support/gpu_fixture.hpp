#pragma once
// GPU tests: a headless Engine (Mesa surfaceless EGL; llvmpipe in CI) with chosen parameters, and for
// tests of the gpu layer itself a bare Device on a headless context with a few drawing helpers.

#include <gtest/gtest.h>

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/vec4.hpp>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "app/engine.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "platform/display.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace glm {
// Texels in failure messages as "(r, g, b, a)".
inline void PrintTo(const u8vec4& v, std::ostream* os) {
    *os << '(' << int(v.r) << ", " << int(v.g) << ", " << int(v.b) << ", " << int(v.a) << ')';
}
}  // namespace glm

namespace puddle::test {

// Parameters from "name=value" strings, as --set takes them; a bad one fails the test.
params::Params make_params(std::initializer_list<std::string> sets);
// Sets "name=value" strings on `params` (command-line layer); a bad one fails the test with its error.
void apply_sets(params::Params& params, const std::vector<std::string>& sets);

// A headless engine of the given size; fails the test (and returns null) when EGL cannot start.
std::unique_ptr<app::Engine> make_engine(const params::Params& params, glm::ivec2 size = {192, 108},
                                         const gpu::DeviceOptions& device = {});

// Runs `frames` frames of `dt` seconds; returns the last frame.
assets::Image render_frames(app::Engine& engine, int frames, double dt = 1.0 / 60.0);

// A headless display's context (64x32) and a Device on it: tests of src/gpu draw through the layer as
// the systems do. The Device dies before the context.
class DeviceFixture : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::unique_ptr<platform::Display> display_;
    std::unique_ptr<gpu::Device> device_;
};

// An RGBA8 texture of `size` texels that passes render into, filled by a clear pass.
gpu::Texture make_target(gpu::Device& device, glm::ivec2 size, glm::vec4 clear);
// A width x 1 RGBA8 texture holding `texels` (RGBA bytes, left to right).
gpu::Texture make_texels(gpu::Device& device, const std::vector<glm::u8vec4>& texels);
// A pipeline that draws its one texture over the whole target (output_canvas.frag, SCALED, no turn):
// set the texture on unit 0 and u_screen_size to the target's size; blend as asked.
gpu::Pipeline make_copy_pipeline(gpu::Device& device, gpu::Blend blend);
// Draws `texture` over all of `target` (sampled nearest, clamped) with `pipeline` in a pass that loads.
void draw_texture(gpu::Device& device, const gpu::Texture& target, const gpu::Pipeline& pipeline,
                  const gpu::Texture& texture);
// Level `level` of an RGBA8 texture as RGBA bytes per texel, rows top first (as Device::read_pixels).
std::vector<glm::u8vec4> read_texels(gpu::Device& device, const gpu::Texture& texture, int level = 0);

}  // namespace puddle::test
