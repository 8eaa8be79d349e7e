#pragma once
// The procedural night sky's clouds, as a layer that drifts: a tiling coverage image, sampled where a
// view direction meets a flat cloud deck one unit above the viewer, so the clouds shrink with perspective
// toward the horizon. The sky cube holds everything else, and in its alpha where clouds may show (open
// sky, fading out toward the horizon; none in front of the buildings); the puddle shader lays the layer
// over the cube at a drifting offset (CLOUD_LAYER in shaders_gles/puddle.frag). Where the cube cannot
// carry that alpha (RGBM), the layer is baked into it once, still.

#include <array>
#include <cstdint>

#include "assets/image.hpp"

namespace puddle::assets {

// One tile of the layer spans this many units of the deck (the deck is one unit up): big enough that
// the repeat is not seen overhead, where a tile spans about 50 degrees of sky.
inline constexpr float cloud_tile_units = 8.0f;
inline constexpr int cloud_layer_size = 256;  // texels per side of the tile

// Coverage in R (0: clear, 255: the thickest cloud), G = B = R, A = 255; RGBA8, cloud_layer_size square,
// tiling in both directions. Value-noise fBm (four octaves, lattices that divide the tile), thresholded
// into broken cloud. The same seed gives the same layer on every machine.
Image cloud_layer_image(std::uint64_t seed = 7);

// Where the unit direction (x, y, z) (y up; below the horizon counts as y = 0) meets the deck, in tiles:
// texture coordinates of the layer before the drift is added. The shader computes the same (u_cloud_scale).
inline std::array<float, 2> cloud_layer_uv(float x, float y, float z) {
    const float k = 1.0f / ((y > 0.0f ? y : 0.0f) + 0.1f) / cloud_tile_units;
    return {x * k, z * k};
}

// Coverage 0..1 at layer coordinates (u, v) in tiles, bilinear and wrapping, as the GPU's sampler reads it.
float cloud_coverage(const Image& layer, float u, float v);

// The light of the drifting clouds, from the procedural sky's palette (linear radiance): the shader runs
// linearly with the ray's height from `base` at the horizon to `top` overhead (no azimuthal city glow, which
// the baked clouds have) and adds `moon_halo` times (cos(angle to the moon) - 0.96) * 25, so the full halo
// at the moon fading to none about 16 degrees away.
struct CloudLight {
    std::array<float, 3> base{};            // near the horizon, lit from below by the city
    std::array<float, 3> top{};             // overhead
    std::array<float, 3> moon_halo{};       // added at the moon, fading to none about 16 degrees away
    std::array<float, 3> moon_direction{};  // unit vector, y up
};

}  // namespace puddle::assets
