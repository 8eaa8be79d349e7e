#pragma once
// The ocean's height map (ocean.method = height_map, the default): once a frame, the height of every
// octave of the sea is laid into a texture that ocean.frag's march and normal read, where the other methods
// compute the waves at every step of every pixel (about 125 octave evaluations a pixel under "secant").
//
// The map lies on the plane y = H of the highest crest and is seen from the eye: its texel (i, j) holds
// the height at the point of that plane seen through the view direction of a point of the view's uv
// (a projected grid; Hinsinger, Neyret and Cani, "Interactive Animation of Ocean Waves", SCA 2002, and
// Johanson, "Real-time water rendering: introducing the projected grid concept", 2004). So it is as fine
// near the eye and as coarse far away as the screen is, at ocean_height_map_scale of the target's pixels
// per side. A ray between its entry into the waves (y = H, which is its own pixel) and the sea's floor
// (y = 0) reads the map at the points of the plane above its steps: those lie on its own pixel and above
// it, toward the horizon, so the map covers the target's window of the view and, above and beside it, the
// points where the rays of its edges reach the floor (ocean_height_map_layout).
//
// The map needs the eye above the crests: when the eye is lower than ocean_height_map_min_eye (the plane
// would be seen edge on or from below), there is no map and the ocean falls back to the secant method.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/view_basis.hpp"
#include "render/view_window.hpp"

namespace puddle::systems {

// Map texels per target pixel, per side: a texel spans about two pixels, so the map costs a quarter of a
// per-pixel evaluation and the normal it gives is filtered over two pixels (far crests do not sparkle).
inline constexpr float ocean_height_map_scale = 0.5f;
// The farthest the march looks (units), ocean.frag's FAR.
inline constexpr float ocean_far = 400.0f;
// The largest map side (texels): beyond it (a video wall's whole view) the texels grow.
inline constexpr int ocean_height_map_max_side = 2048;

// The highest a crest can reach (units) for ocean.height and ocean.octaves: 2 * height * sum of 0.22^i,
// ocean_waves.glsl's highest_wave().
float ocean_highest_wave(float height, int octaves);
// The lowest eye (units above the sea's floor) that the map serves: 1.25 H + 0.05.
float ocean_height_map_min_eye(float highest_wave);

// Where the map lies in the view, and its size.
struct OceanHeightMapLayout {
    glm::vec2 origin{0, 0};  // its bottom-left corner in the whole view's uv (may lie outside 0..1)
    glm::vec2 extent{0, 0};  // its size in the whole view's uv
    glm::ivec2 size{0, 0};   // texels; (0, 0): no map (the eye too low, or no sea in the window)
    float plane = 0;         // y of the plane it lies on (units): the highest crest

    bool empty() const { return size.x <= 0 || size.y <= 0; }
    // u_map_window: (origin, extent), what ocean.frag maps view uv to map coordinates by.
    glm::vec4 uniform() const { return {origin, extent}; }
};

// The map for a target of `target_size` pixels showing `window` of the view, seen from `eye` through
// `view` (the whole view's camera), over waves no higher than `highest_wave`. It covers the window's part
// that sees the sea within ocean_far, and the points of the plane above where its rays reach the floor
// (found on a 17 x 17 grid of the window's rays, with a margin of one grid spacing), never more than the
// window's own size again beyond each side. Pure: the same inputs give the same layout.
OceanHeightMapLayout ocean_height_map_layout(const render::ViewBasis& view, glm::vec3 eye, float highest_wave,
                                             const render::ViewWindow& window, glm::ivec2 target_size);

// The angle (radians) a texel of `layout` spans at the centre of the view, seen through `view`: what the
// height pass fades the octaves a texel cannot hold by (ocean_waves.glsl's sea_height_filtered).
float ocean_texel_angle(const render::ViewBasis& view, const OceanHeightMapLayout& layout);

}  // namespace puddle::systems
