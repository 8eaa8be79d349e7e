#pragma once
// The puddle shader's compile-time variants. Choices that are the same for every pixel and change only
// when someone turns a knob or edits the config (render method, ground kind, RGBM sky, tone curve)
// become #defines, so the shader carries only the path it takes: no pixel pays for a branch it never
// takes, and nothing is computed for a ground the water hides. Each variant is compiled the first time
// it is needed (systems/puddle/render_system.cpp).

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "params/param_store.hpp"

namespace puddle::render {

// Paving: the procedural wet setts, drawn by the shader (no texture, about the checkerboard's cost);
// Image: ground.image, a texture.
enum class GroundKind { Checkerboard, Paving, Image, Hidden };
inline constexpr std::size_t ground_kind_count = 4;

struct PuddleVariant {
    bool raymarch = false;
    bool shore = false;  // puddle.shape = shore (with the intersect method only)
    GroundKind ground = GroundKind::Checkerboard;
    bool env_rgbm = false;
    bool cloud_layer = false;  // the procedural sky's drifting clouds over a cube with room for them
    params::Tonemap tonemap = params::Tonemap::clip;  // its index is TONEMAP_* in colour.glsl

    bool operator==(const PuddleVariant&) const = default;
};

inline constexpr std::size_t tonemap_count = params::choice_count<params::Tonemap>;
inline constexpr std::size_t puddle_variant_count = 2 * 2 * ground_kind_count * 2 * 2 * tonemap_count;

// True when turbidity leaves the ground less than 1/4096 of its brightness even along the shortest path
// through the water (straight down from the highest crest): then the refraction is skipped, and the
// picture differs from the full computation by under one 8-bit level (a test compares them).
bool ground_hidden(const params::Params& params);

// The variant for these parameters; env_rgbm: the cube sampled this frame holds RGBM texels; cloud_layer:
// it is the procedural sky made with room for the drifting clouds (never with RGBM).
PuddleVariant choose_puddle_variant(const params::Params& params, bool env_rgbm, bool cloud_layer = false);

// A dense index in [0, puddle_variant_count), for a fixed table of pipelines.
std::size_t variant_index(const PuddleVariant& v);

// The #defines puddle.frag takes for a variant; surface_unorm: the surface is the RGBA8 fallback.
std::vector<std::string> variant_defines(const PuddleVariant& v, bool surface_unorm);

// "intersect, checkerboard, soft": for the log line that says a variant was built.
std::string describe(const PuddleVariant& v);

}  // namespace puddle::render
