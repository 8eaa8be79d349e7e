// The rain streaks' cells (REFERENCE.md section 3's four parallax layers): each layer cuts the whole view
// into tall cells, and a cell, by its own hash, holds one thin streak or none. rain_streaks.vert places a
// quad on each streak; rain_streaks.frag shades it. Needs hash.glsl.

uniform vec2 u_resolution;  // the whole view (a whole video wall) in pixels of this target
uniform int u_seed;
uniform float u_overlay_rain_density;
uniform float u_streak_strength;  // the rain's current strength as a factor of the density (rain_overlay_system.hpp)

const int STREAK_LAYERS = 4;
// scale, density, weight: far and small to near and large (their fall speeds are on the CPU).
const vec3 LAYERS[4] = vec3[4](vec3(80.0, 0.40, 0.25), vec3(50.0, 0.50, 0.45), vec3(30.0, 0.55, 0.70),
                               vec3(18.0, 0.35, 0.90));

// The layer's cells across and up the whole view (the top row may be cut by the view's edge).
vec2 streak_cells(int layer) { return vec2(LAYERS[layer].x * 1.5, LAYERS[layer].x * 0.15); }
// Whole and cut cells: 80 * 0.15 may round to just over 12 in float, which covers no pixel.
ivec2 streak_cell_counts(int layer) { return ivec2(ceil(streak_cells(layer) - 1e-3)); }
uint streak_salt(int layer) { return uint(u_seed) * 8u + uint(layer) * 2u; }
bool streak_present(int layer, ivec2 cell) {
    return hash_cell(cell, streak_salt(layer)) < LAYERS[layer].y * u_overlay_rain_density * u_streak_strength;
}
// 0..1: where across the cell the streak falls (0.2 + 0.6 of it) and how far along its fall it starts.
float streak_offset(int layer, ivec2 cell) { return hash_cell(cell, streak_salt(layer) + 1u); }
// Half the streak's width in cells: a tenth of a cell, never thinner than about a pixel (thinner would
// flicker).
float streak_half_width(int layer) { return max(0.05, 0.6 * streak_cells(layer).x / u_resolution.x); }
// A streak is lit where its fall, in cells modulo 1, is in 0..STREAK_LENGTH.
const float STREAK_LENGTH = 0.25;
