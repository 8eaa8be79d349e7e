#version 300 es
// Rain streaks over any scene (REFERENCE.md section 3): four parallax layers; each cuts the screen into tall
// cells, and a cell, by its own hash, holds one thin streak or none. The pass blends as light (Blend::Lit:
// the target times 1 + this output): a streak lights up by what lies behind it, bright in front of lit
// windows and their reflections, all but invisible against the dark, as rain at night is seen.
precision highp float;
precision highp int;

#include "hash.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

// Per layer, far to near: how far its streaks have fallen, in cells modulo 1 (a streak's fall repeats
// every cell), from the CPU in double (systems/rain_overlay/rain_overlay_system.hpp), so rain never jumps.
uniform vec4 u_layer_fall;
uniform vec2 u_resolution;    // the whole view (a whole video wall) in pixels of this target
uniform int u_seed;
uniform float u_overlay_rain_density;
uniform float u_streak_strength;  // the rain's current strength as a factor of the density (rain_overlay_system.hpp)
uniform float u_overlay_rain_speed;
uniform vec3 u_overlay_rain_color;
uniform float u_overlay_rain_opacity;

// scale, density, weight: far and small to near and large (their fall speeds are on the CPU).
const vec3 LAYERS[4] = vec3[4](vec3(80.0, 0.40, 0.25), vec3(50.0, 0.50, 0.45), vec3(30.0, 0.55, 0.70),
                               vec3(18.0, 0.35, 0.90));

float layer(vec3 L, float fallen, uint salt) {
    vec2 cells = vec2(L.x * 1.5, L.x * 0.15);
    vec2 p = v_uv * cells;
    ivec2 cell = ivec2(floor(p));
    vec2 local = fract(p);
    float present = step(hash_cell(cell, salt), L.y * u_overlay_rain_density * u_streak_strength);
    float offset = hash_cell(cell, salt + 1u);
    // A streak a tenth of a cell wide, never thinner than about a pixel (thinner would flicker).
    float half_width = max(0.05, 0.6 * cells.x / u_resolution.x);
    float across = 1.0 - smoothstep(0.5 * half_width, half_width, abs(local.x - (0.2 + 0.6 * offset)));
    float fall = fract(local.y + fallen + offset);
    float along = smoothstep(0.0, 0.04, fall) * smoothstep(0.25, 0.0, fall);
    return present * across * along * L.z;
}

void main() {
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += layer(LAYERS[i], u_layer_fall[i], uint(u_seed) * 8u + uint(i) * 2u);
    // At full opacity the nearest streak doubles what is behind it, tinted by overlay.rain_color.
    o_color = vec4(u_overlay_rain_color * (clamp(sum, 0.0, 1.0) * u_overlay_rain_opacity / 0.9 * 1.25), 1.0);
}
