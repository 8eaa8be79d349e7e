#pragma once
// Turns an equirectangular panorama into a cube map on the GPU, once at load: one pass per face and mip
// level, each filtering the panorama over its texels' footprint (so RGBM levels are true averages of
// radiance). The caller picks the cube's format (environment_system.cpp). The CPU half (the panorama's
// mip chain) runs on any thread; the GPU half runs on the frame thread in bounded steps, so converting a
// large panorama while the display runs never holds up a frame for long.

#include <stop_token>
#include <vector>

#include "assets/image.hpp"
#include "gpu/device.hpp"
#include "render/pipeline_cache.hpp"
#include "util/result.hpp"

namespace puddle::render {

// The face size `environment.face_size = 0` picks: a quarter of the panorama's width (one face spans a
// quarter of the horizon), at most 1024 and at most what the GPU takes.
int auto_face_size(int panorama_width, int max_cube_size);

// Makes an environment cube (kind Cube, a full mip chain, a render target) of `face_size`. When it does not
// fit in GPU memory (exit code GpuMemory), tries half the size while that is at least
// `smallest_face_size`, and logs one warning naming the size it used. The error, when none fits, is the
// one for `face_size`, saying how far down it tried.
Result<gpu::Texture> create_environment_cube(gpu::Device& device, gpu::TextureFormat format, int face_size,
                                             int smallest_face_size);

// CPU only, any thread. The panorama as the conversion samples it, level 0 first: halved until it is at
// most `max_texture_size` wide (8k and 16k panoramas exist; many GPUs stop at 4k); then, for a float
// panorama, every mip level averaged from the one above (half floats filter everywhere in GLES 3.0, but
// the GPU makes their mipmaps only where it can render into them). An 8-bit panorama gets level 0 only:
// the GPU makes its mipmaps. Returns early, incomplete, once `stop` is requested.
std::vector<assets::Image> panorama_mip_chain(assets::Image panorama, int max_texture_size,
                                              std::stop_token stop = {});

// What the conversion writes: linear or sRGB texels as they are, or RGBM (each its own shader).
enum class CubeEncoding { plain, rgbm };
// The conversion's pipelines, built (off the frame thread) the first time a panorama is converted to that
// encoding and kept by the caller for later conversions: a sky reloaded at run time compiles nothing.
using EquirectPipelines = PipelineCache<CubeEncoding, 2, enum_index<CubeEncoding>>;

// The GPU half, on the frame thread, one bounded step at a time.
class EquirectToCube {
public:
    // `levels`: panorama_mip_chain's output (RGBA8 sRGB or RGBA32F linear, width = 2 * height).
    // `format`: SRGB8_A8, RGBA16F or (with `rgbm`) RGBA8 holding RGBM texels.
    // The cube is made by create_environment_cube: where `face_size` does not fit, a smaller one down to
    // `smallest_face_size` (take_cube().width() says which).
    EquirectToCube(std::vector<assets::Image> levels, int face_size, gpu::TextureFormat format, bool rgbm,
                   int smallest_face_size);

    // Does the next step: makes the panorama texture, uploads one band of rows of a panorama level, makes
    // the panorama's mipmaps, checks on the pipeline (from `pipelines`; while it builds the step does
    // nothing), makes the cube, or renders one band of rows of one face and level of the cube; a band is
    // at most `texel_budget` texels.
    // True once the cube is complete; an error (the shader does not build, a texture does not fit in
    // GPU memory: ExitCode::GpuMemory) ends the conversion.
    Result<bool> step(gpu::Device& device, long texel_budget, EquirectPipelines& pipelines);
    gpu::Texture take_cube() { return std::move(cube_); }

private:
    enum class Phase { Upload, Mipmaps, Pipeline, Cube, Render, Done };
    std::vector<assets::Image> levels_;  // freed as they are uploaded
    int panorama_width_ = 0, panorama_height_ = 0, panorama_mips_ = 1;
    int face_size_;
    int smallest_face_size_;
    gpu::TextureFormat format_;
    bool rgbm_;
    Phase phase_ = Phase::Upload;
    gpu::Texture panorama_;
    gpu::Sampler sampler_;
    const gpu::Pipeline* pipeline_ = nullptr;  // in the caller's EquirectPipelines
    gpu::Texture cube_;
    std::size_t uploaded_ = 0;            // panorama levels uploaded
    int upload_row_ = 0;                  // the next row of the level being uploaded
    int level_ = 0, face_ = 0, row_ = 0;  // the next band of the cube to render
};

// All of it at once (start-up and tests): the mip chain, then every step, with pipelines of its own.
Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& panorama, int face_size,
                                      gpu::TextureFormat format, bool rgbm, int smallest_face_size);

}  // namespace puddle::render
