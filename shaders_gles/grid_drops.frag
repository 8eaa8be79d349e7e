#version 300 es
// Grid-sampled drops (REFERENCE.md section 5): the field is cut into square cells holding one drop each;
// a texel tests only the drops of its own cell and its neighbours (GRID_REACH 1: 3x3), so the cost does
// not depend on how many drops fall. Each cell's drop respawns at a new spot when its ring, grown to half a
// cell, fades out. Writes the same surface as surface.frag (height, hL - hR, hD - hU).
precision highp float;
precision highp int;

#include "hash.glsl"
#include "surface_encoding.glsl"

#ifndef GRID_REACH
#define GRID_REACH 1
#endif

uniform float u_cell_texels;   // cell size in field texels
uniform int u_cycle_base;      // floor(time / grid.cycle) modulo 2^32 (a uint's bits), split on the CPU
uniform float u_cycle_fraction;
uniform int u_seed;
uniform ivec2 u_only_cell;     // tests: only this cell's drop (x < 0: every cell)
uniform float u_grid_amplitude;
uniform float u_grid_ring_width;

out vec4 o_surface;

// A ring's profile across its width u (in ring widths): a crest with a trough each side, exactly zero
// from |u| = 2, so a ring of radius at most half a cell stays within a cell of its own.
float ring_profile(float u) { return cos(2.0 * u) * exp(-u * u) * (1.0 - smoothstep(1.5, 2.0, abs(u))); }

float height(vec2 p) {  // p in cells
    ivec2 home = ivec2(floor(p));
    float h = 0.0;
    for (int dy = -GRID_REACH; dy <= GRID_REACH; ++dy) {
        for (int dx = -GRID_REACH; dx <= GRID_REACH; ++dx) {
            ivec2 cell = home + ivec2(dx, dy);
            if (u_only_cell.x >= 0 && cell != u_only_cell) continue;
            uint id = hash3(uint(cell.x), uint(cell.y), uint(u_seed));
            float s = u_cycle_fraction + unit_float(mix_bits(id));  // the cell's own time offset
            uint cycle = uint(u_cycle_base) + uint(floor(s));  // uint: wraps at 2^32 like the CPU's count
            float age = fract(s);  // 0..1 over the cycle
            vec2 drop = vec2(cell) + vec2(unit_float(hash3(id, cycle, 1u)), unit_float(hash3(id, cycle, 2u)));
            float u = (distance(p, drop) - 0.5 * age) / u_grid_ring_width;
            h += u_grid_amplitude * smoothstep(0.0, 0.05, age) * (1.0 - age) * ring_profile(u);
        }
    }
    return h;
}

void main() {
    vec2 p = gl_FragCoord.xy / u_cell_texels;
    float texel = 1.0 / u_cell_texels;
    float hL = height(p - vec2(texel, 0.0));
    float hR = height(p + vec2(texel, 0.0));
    float hD = height(p - vec2(0.0, texel));
    float hU = height(p + vec2(0.0, texel));
    o_surface = vec4(encode_surface(vec3(height(p), hL - hR, hD - hU)), 0.0);  // alpha: no splashes
}
