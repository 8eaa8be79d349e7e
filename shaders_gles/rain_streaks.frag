#version 300 es
// Rain streaks over any scene (REFERENCE.md section 3): four parallax layers; each cuts the screen into tall
// cells, and a cell, by its own hash, holds one thin streak or none. The pass blends by alpha.
precision highp float;
precision highp int;

#include "hash.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform float u_time;         // seconds, wrapped on the CPU to keep float precision
uniform vec2 u_resolution;    // pixels
uniform int u_seed;
uniform float u_overlay_rain_density;
uniform float u_overlay_rain_speed;
uniform vec3 u_overlay_rain_color;
uniform float u_overlay_rain_opacity;

// scale, speed, density, weight: far, small and slow to near, large and fast.
const vec4 LAYERS[4] = vec4[4](vec4(80.0, 1.8, 0.40, 0.25), vec4(50.0, 2.5, 0.50, 0.45),
                               vec4(30.0, 3.2, 0.55, 0.70), vec4(18.0, 3.8, 0.35, 0.90));

float layer(vec4 L, uint salt) {
    vec2 cells = vec2(L.x * 1.5, L.x * 0.15);
    vec2 p = v_uv * cells;
    ivec2 cell = ivec2(floor(p));
    vec2 local = fract(p);
    float present = step(hash_cell(cell, salt), L.z * u_overlay_rain_density);
    float offset = hash_cell(cell, salt + 1u);
    // A streak a tenth of a cell wide, never thinner than about a pixel (thinner would flicker).
    float half_width = max(0.05, 0.6 * cells.x / u_resolution.x);
    float across = 1.0 - smoothstep(0.5 * half_width, half_width, abs(local.x - (0.2 + 0.6 * offset)));
    float fall = fract(local.y + u_time * L.y * u_overlay_rain_speed + offset);
    float along = smoothstep(0.0, 0.04, fall) * smoothstep(0.25, 0.0, fall);
    return present * across * along * L.w;
}

void main() {
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += layer(LAYERS[i], uint(u_seed) * 8u + uint(i) * 2u);
    o_color = vec4(u_overlay_rain_color, clamp(sum, 0.0, 1.0) * u_overlay_rain_opacity);
}
