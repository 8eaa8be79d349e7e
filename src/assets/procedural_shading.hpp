#pragma once
// Small shading helpers shared by the procedural sky's parts (procedural.cpp, procedural_city.cpp): a
// linear-light colour vector, integer hashes and value noise. Internal to src/assets.

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace puddle::assets::shading {

struct Vec3 {
    float x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(Vec3 a, float s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline Vec3 operator*(Vec3 a, Vec3 b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
inline Vec3 mix(Vec3 a, Vec3 b, float t) {
    return a + (b - a) * t;
}
inline float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 normalize(Vec3 a) {
    return a * (1.0f / std::sqrt(dot(a, a)));
}

inline constexpr float kPi = 3.14159265f;
inline constexpr float kDeg = kPi / 180.0f;

inline float clamp01(float v) {
    return std::clamp(v, 0.0f, 1.0f);
}
inline float smoothstep(float e0, float e1, float x) {
    const float t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3.0f - 2.0f * t);
}
// An sRGB byte triple as linear light: colours are picked by eye in sRGB.
inline Vec3 srgb(float r, float g, float b) {
    const auto lin = [](float c) {
        c /= 255.0f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    return {lin(r), lin(g), lin(b)};
}

// Integer hashing (Wellons' lowbias32): the same sky on every machine, no rand() state.
inline std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
inline std::uint32_t hash(std::uint32_t a, std::uint32_t b) {
    return hash(a ^ hash(b + 0x9e3779b9U));
}
inline std::uint32_t hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return hash(a, hash(b, c));
}
inline std::uint32_t as_u32(int i) {
    return static_cast<std::uint32_t>(i);
}
// A hash as a float in [0, 1).
inline float unit(std::uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

inline float value_noise(float x, float y, std::uint32_t key) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    // One hash per lattice corner (noise is the hot spot): mix the coordinates, then hash once.
    const std::uint32_t hx = as_u32(ix) * 0x8da6b343U, hy = as_u32(iy) * 0xd8163841U;
    const float a = unit(hash(hx ^ hy ^ key));
    const float b = unit(hash((hx + 0x8da6b343U) ^ hy ^ key));
    const float c = unit(hash(hx ^ (hy + 0xd8163841U) ^ key));
    const float d = unit(hash((hx + 0x8da6b343U) ^ (hy + 0xd8163841U) ^ key));
    return a + (b - a) * tx + (c - a) * ty + (a - b - c + d) * tx * ty;
}

// Four octaves, each rotated so the lattice does not show; result roughly in [0, 1].
inline float fbm(float x, float y, std::uint32_t key) {
    float sum = 0.0f, amp = 0.5f;
    for (int o = 0; o < 4; ++o) {
        sum += amp * value_noise(x, y, key + as_u32(o));
        const float nx = 1.6f * x + 1.2f * y, ny = -1.2f * x + 1.6f * y;
        x = nx + 17.0f;
        y = ny - 5.0f;
        amp *= 0.5f;
    }
    return sum / 0.9375f;
}

// Coverage of a pixel of width w centred at x by the interval [lo, hi]: antialiased edges.
inline float cover(float x, float lo, float hi, float w) {
    return clamp01(std::min(x - lo, hi - x) / w + 0.5f);
}

}  // namespace puddle::assets::shading
