#version 300 es
// One step of the wave field, stored as (next, current).
//
// Reference (REFERENCE.md section 1): the damped discrete 2D wave equation,
//   next = 0.5 * (damping * (L + R + D + U - 2 * prev) + disturbance); edges clamp, so the border reflects.
//
// CAPILLARY: ripples of rain on shallow water. A leapfrog step of
//   h_tt = c^2 lap(h) - beta lap(lap(h)) + 2 nu lap(h_t) - drag h_t - w0^2 h + sources,
// whose plane waves obey w^2 = c^2 k^2 + beta k^4 + w0^2 (capillary-gravity dispersion, Lamb,
// Hydrodynamics section 266, with c and beta fitted to centimetre ripples; w0, far below any ripple's
// frequency, returns the water to its level) and whose amplitude fades at nu k^2 + drag / 2 (viscous
// damping, Lamb section 348, whose deep-water rate is 2 nu k^2). In texel units with the factors of
// u_step (systems/water/capillary_step.hpp):
//   next = h + keep (h - prev) + a lap(h) - b lap2(h) + v lap(h - prev) + sources.
// The field is periodic (it repeats across the puddle). Rain falls here, hashed per cell and time slot,
// so any number of drops costs the same: each cell of the rain grid gets at most one drop per slot, with
// a hashed chance, place and time, of a Marshall-Palmer size, read from the rain cells' table made for
// this pass (rain_cells.frag); u_drops adds explicit ones.
// FIXED_POINT_SCALE selects the RG32I fallback field.
precision highp float;
precision highp int;


#ifdef FIXED_POINT_SCALE
uniform highp isampler2D u_field;
layout(location = 0) out ivec2 o_field;
vec2 load(ivec2 p) { return vec2(texelFetch(u_field, p, 0).rg) / FIXED_POINT_SCALE; }
#else
uniform highp sampler2D u_field;
layout(location = 0) out vec2 o_field;
vec2 load(ivec2 p) { return texelFetch(u_field, p, 0).rg; }
#endif

uniform int u_drop_count;
layout(std140) uniform Drops {
    // reference: x, y in texels; z = strength * activation.
    // CAPILLARY: x, y in texels; z = drop diameter in mm; w = seconds since it hit.
    vec4 u_drops[MAX_DROPS];
};

#ifndef CAPILLARY
uniform float u_wave_damping;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 hi = textureSize(u_field, 0) - 1;
    float L = load(clamp(p - ivec2(1, 0), ivec2(0), hi)).r;
    float R = load(clamp(p + ivec2(1, 0), ivec2(0), hi)).r;
    float D = load(clamp(p - ivec2(0, 1), ivec2(0), hi)).r;
    float U = load(clamp(p + ivec2(0, 1), ivec2(0), hi)).r;
    vec2 here = load(p);  // (current, previous)

    float disturbance = 0.0;
    for (int i = 0; i < u_drop_count; ++i) {
        vec4 d = u_drops[i];
        float r = distance(gl_FragCoord.xy, d.xy);  // in texels
        disturbance += d.z * smoothstep(4.0, 0.5, r);
    }

    float next = 0.5 * (u_wave_damping * (L + R + D + U - 2.0 * here.g) + disturbance);
#ifdef FIXED_POINT_SCALE
    // Keep the current height bit-exact as the next step's previous height.
    o_field = ivec2(int(round(next * FIXED_POINT_SCALE)), texelFetch(u_field, p, 0).r);
#else
    o_field = vec2(next, here.r);
#endif
}
#else
uniform vec4 u_step;        // a, b, v, keep (systems/water/capillary_step.hpp)
uniform float u_level;      // w0^2 dt^2: the pull back to the water's level
uniform bool u_impacts_on;     // the rain cells' table holds this pass's drops

#include "drop_impulse.glsl"
#include "rain_cells.glsl"

ivec2 n_texels;
// The field `d` texels from this one, wrapped around its edges (periodic) by the sampler's repeat: an
// integer % per read was most of the step's cost on llvmpipe, which has no vector division.
vec2 here_uv;
#ifdef FIXED_POINT_SCALE
#define AT(dx, dy) (vec2(textureLodOffset(u_field, here_uv, 0.0, ivec2(dx, dy)).rg) / FIXED_POINT_SCALE)
#else
#define AT(dx, dy) textureLodOffset(u_field, here_uv, 0.0, ivec2(dx, dy)).rg
#endif

float impulse(float r, float d, float t) {
    float radius = drop_radius_texels(d);
    return drop_push(d, t) * ring_profile(r * r / (radius * radius));
}

// The rain's rings: the drops of the 2x2 cells that can reach p, this slot's and the last's.
float rain(vec2 p) {
    ivec2 c0 = rain_cells_near(p);
    float sum = 0.0;
    for (int j = 0; j < 8; ++j) {
        vec2 spot;
        vec4 drop = rain_cell(c0 + ivec2(j & 1, (j >> 1) & 1), j >> 2, 0, spot);
        vec2 d = p - spot;
        sum += drop.w * ring_profile(dot(d, d) * drop.z);
    }
    return sum;
}

void main() {
    n_texels = textureSize(u_field, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    here_uv = gl_FragCoord.xy / vec2(n_texels);  // the texel's centre: nearest reads it exactly
    vec2 here = AT(0, 0);  // (current, previous)
    vec2 l = AT(-1, 0), r = AT(1, 0), d = AT(0, -1), u = AT(0, 1);
    vec2 lap = l + r + d + u - 4.0 * here;  // of the current (x) and previous (y) heights
    float diagonals = AT(-1, -1).r + AT(1, -1).r + AT(-1, 1).r + AT(1, 1).r;
    float far = AT(-2, 0).r + AT(2, 0).r + AT(0, -2).r + AT(0, 2).r;
    float lap2 = 20.0 * here.r - 8.0 * (l.r + r.r + d.r + u.r) + 2.0 * diagonals + far;

    float next = here.r + u_step.w * (here.r - here.g) + u_step.x * lap.x - u_step.y * lap2 +
                 u_step.z * (lap.x - lap.y) - u_level * here.r;
    vec2 centre = gl_FragCoord.xy;
    if (u_impacts_on) next += rain(centre);
    for (int i = 0; i < u_drop_count; ++i) {
        vec4 drop = u_drops[i];
        vec2 offset = centre - drop.xy;
        offset -= vec2(n_texels) * round(offset / vec2(n_texels));  // the nearest of its periodic copies
        next += impulse(length(offset), drop.z, drop.w + u_drop_shape.z);
    }
#ifdef FIXED_POINT_SCALE
    o_field = ivec2(int(round(next * FIXED_POINT_SCALE)), texelFetch(u_field, p, 0).r);
#else
    o_field = vec2(next, here.r);
#endif
}
#endif
