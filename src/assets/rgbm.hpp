#pragma once
// RGBM: 8-bit storage of HDR radiance for GPUs that cannot render into half-float textures (the RGBE
// idea of a shared scale, with the scale linear): colour = rgb * m * RGBM_RANGE, m in alpha. A linear
// scale survives texture filtering better than a shared exponent: halfway between a lit window's texel
// and a dark wall's, filtering gives over half their average radiance (a shared exponent, a twentieth).
// Mip levels are made from linear averages, never by glGenerateMipmap. Radiance up to RGBM_RANGE (16, four
// stops past white) is kept; more saturates, which after tone mapping still reads as full brightness.
// shaders_gles/colour.glsl holds the same encoding for the GPU; both must stay in step.

#include <array>
#include <cstdint>

#include "assets/image.hpp"

namespace puddle::assets {

inline constexpr float rgbm_range = 16.0f;

std::array<std::uint8_t, 4> encode_rgbm(const float* rgb);
std::array<float, 3> decode_rgbm(const std::uint8_t* rgbm);
// An RGBA32F image as RGBA8 RGBM texels.
Image encode_rgbm(const Image& linear);

}  // namespace puddle::assets
