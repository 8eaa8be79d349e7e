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

// `panorama`: RGBA8 sRGB or RGBA32F linear, width = 2 * height. `format`: SRGB8_A8, RGBA16F or (with
// `rgbm`) RGBA8 holding RGBM texels.
Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& panorama, int face_size,
                                      gpu::TextureFormat format, bool rgbm);

}  // namespace puddle::systems
