#pragma once
// A new environment cube made in two halves, so that even an 8192x4096 panorama at face size 4096 never
// holds up a frame for long: prepare_environment() is the CPU half and runs on any thread (reading and
// decoding the files, shrinking to the GPU's limits, making the mip levels the GPU cannot make, RGBM
// encoding); EnvironmentBuild is the GPU half and runs on the frame thread in bounded steps (one band of
// rows uploaded, one mipmap generation, one shader build, or one band of a panorama conversion pass).

#include <array>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "assets/image.hpp"
#include "gpu/capabilities.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/equirect_to_cube.hpp"
#include "util/result.hpp"

namespace puddle::systems {

struct Environment;

// What a new environment needs to know, as plain values a worker thread may read.
struct EnvironmentRequest {
    std::string image;  // environment.image: empty for the procedural night sky
    int face_size = 0;  // environment.face_size: 0 picks one from the panorama's width
    int max_cube_map_size = 2048, max_texture_size = 2048;
    bool half_float_render_targets = false;

    static EnvironmentRequest from(const params::Params& params, const gpu::Capabilities& caps);
};

// The CPU half's result: every texel the GPU half uploads.
struct PreparedEnvironment {
    std::string source;  // for logs
    bool hdr = false;
    bool rgbm = false;        // HDR stored as RGBM RGBA8 (no half-float render targets)
    bool cloud_room = false;  // alpha: how much the drifting cloud layer may cover (procedural sky)
    gpu::TextureFormat format = gpu::TextureFormat::SRGB8_A8;
    int face_size = 0;
    // Six faces (or a cube cross) from files: cube_levels[level][face], only level 0 when the GPU makes
    // the mipmaps (sRGB and half float), every level for RGBM.
    std::vector<std::array<assets::Image, 6>> cube_levels;
    // A panorama, converted on the GPU: its mip chain (panorama_mip_chain).
    std::vector<assets::Image> panorama_levels;
};

// CPU only, any thread. Errors are start-up errors (exit code 3) naming the file and why; a requested
// `stop` returns early with an error that says so.
Result<PreparedEnvironment> prepare_environment(const EnvironmentRequest& request, std::stop_token stop = {});

// The GPU half, on the frame thread.
class EnvironmentBuild {
public:
    // Texels one step uploads or renders at most. Measured on Mesa llvmpipe on two busy cores: a million
    // take 50 ms to upload as half floats and 120 to 220 ms to render from a panorama.
    static constexpr long texels_per_step = 1L << 20;

    // Where the cube asked for does not fit in GPU memory, smaller faces are tried down to
    // `fallback_floor` (create_environment_cube); no_fallback: the size asked for or an error.
    static constexpr int no_fallback = 1 << 30;
    EnvironmentBuild(PreparedEnvironment prepared, int fallback_floor);
    // Does the next step; true once the cube is complete. An error ends the build (ExitCode::GpuMemory
    // for a cube that does not fit at any size allowed). A panorama is converted with `pipelines`' shader
    // (built on first use, kept by the caller for later builds), which must outlive the build.
    Result<bool> step(gpu::Device& device, render::EquirectPipelines& pipelines);
    // The finished environment (after step() returned true) into `env`; logs the line that says what is
    // shown. Leaves env's requested_* values as they are.
    void finish(gpu::Device& device, Environment& env);

private:
    PreparedEnvironment prepared_;
    int smallest_face_size_;
    std::optional<render::EquirectToCube> conversion_;
    gpu::Texture cube_;
    std::size_t level_ = 0, face_ = 0;  // the next face image to upload
    int row_ = 0;                       // and its next row
    bool mipmaps_due_ = false;
};

}  // namespace puddle::systems
