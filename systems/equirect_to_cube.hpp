#pragma once
// Turns an equirectangular panorama into a cube map on the GPU, once at load: one pass per face and mip
// level, each filtering the panorama over its texels' footprint (so RGBM levels are true averages of
// radiance). The caller picks the cube's format (environment_system.cpp).

#include "assets/image.hpp"
#include "gpu/device.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// The face size `environment.face_size = 0` picks: a quarter of the panorama's width (one face spans a
// quarter of the horizon), at most 1024 and at most what the GPU takes.
int auto_face_size(int panorama_width, int max_cube_size);

// Makes an environment cube (kind Cube, a full mip chain, a render target) of `face_size`. When it does not
// fit in GPU memory (exit code GpuMemory), tries half the size while that is at least
// `smallest_face_size`, and logs one warning naming the size it used. The error, when none fits, is the
// one for `face_size`, saying how far down it tried.
Result<gpu::Texture> create_environment_cube(gpu::Device& device, gpu::TextureFormat format, int face_size,
                                             int smallest_face_size);

// `panorama`: RGBA8 sRGB or RGBA32F linear, width = 2 * height. `format`: SRGB8_A8, RGBA16F or (with
// `rgbm`) RGBA8 holding RGBM texels. The cube is made by create_environment_cube: its width says the
// face size used.
Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& panorama, int face_size,
                                      gpu::TextureFormat format, bool rgbm, int smallest_face_size);

}  // namespace puddle::systems
