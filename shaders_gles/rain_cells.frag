#version 300 es
// The rain cells' table for one pass of the wave step: each cell of the rain grid, for this slot and the
// one before (k), hashed once here (rain_impacts.glsl) instead of in every texel the drop can reach. The
// step and the surface pass then read 8 texels of it a texel (rain_cells.glsl) where they hashed 8
// candidates with a logarithm, three sines and two square roots each: on llvmpipe, which runs both sides
// of every branch, that was half the step's time. Texel (2 cell.x + k, 2 cell.y + part), as the bits of
// floats (RGBA32I renders everywhere GLES 3 does):
//   part 0, the ring impulse at this pass's time: where in the cell (0..1 each way), 1 / radius^2 in
//           texels, the push at the centre (height units; 0: none);
//   part 1, the splash: where in the cell, seconds since the hit (-1: none), diameter (mm).
precision highp float;
precision highp int;

#include "hash.glsl"
#include "rain_impacts.glsl"

#include "drop_impulse.glsl"

layout(location = 0) out ivec4 o_cell;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 cell = p >> 1;
    int k = p.x & 1;
    bool splash = (p.y & 1) == 1;
    vec2 within;
    float age, diameter;
    vec4 v = splash ? vec4(0.0, 0.0, -1.0, 0.0) : vec4(0.0, 0.0, 1.0, 0.0);
    if (rain_impact(cell, k, splash ? SPLASH_SECONDS : RAIN_SLOT, within, age, diameter)) {
        float r = drop_radius_texels(diameter);
        v = splash ? vec4(within, age, diameter) : vec4(within, 1.0 / (r * r), drop_push(diameter, age));
    }
    o_cell = floatBitsToInt(v);
}
