#pragma once
// The integer hashes of shaders_gles/hash.glsl on the CPU, bit for bit, for values a system computes for
// a shader that the shader used to draw itself (the street's source periods). Keep the two in step.

#include <cstdint>

namespace puddle::render {

constexpr std::uint32_t shader_mix_bits(std::uint32_t x) {
    x ^= x >> 15u;
    x *= 0x2c1b3c6du;
    x ^= x >> 12u;
    x *= 0x297a2d39u;
    x ^= x >> 15u;
    return x;
}

constexpr std::uint32_t shader_hash3(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return shader_mix_bits(a ^ shader_mix_bits(b ^ shader_mix_bits(c + 0x9e3779b9u)));
}

// 0..1 from the top 24 bits (exact in a float and a double).
constexpr double shader_unit_float(std::uint32_t h) {
    return static_cast<double>(h >> 8u) / 16777216.0;
}

}  // namespace puddle::render
