#version 300 es
// Folds what the render pass needs from the height field into one filterable texel per field texel:
// height and its central differences one texel apart (hL - hR, hD - hU). Filtering these linearly equals
// differencing linearly filtered heights, so the render pass takes one fetch where it would take five.
// PERIODIC: the field repeats (a capillary field), so the differences wrap around its edges.
precision highp float;
precision highp int;

#include "surface_encoding.glsl"

#ifdef FIXED_POINT_SCALE
uniform highp isampler2D u_field;
float height(ivec2 p) { return float(texelFetch(u_field, p, 0).r) / FIXED_POINT_SCALE; }
#else
uniform highp sampler2D u_field;
float height(ivec2 p) { return texelFetch(u_field, p, 0).r; }
#endif

out vec4 o_surface;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef PERIODIC
    ivec2 n = textureSize(u_field, 0);
    float hL = height((p - ivec2(1, 0) + n) % n);
    float hR = height((p + ivec2(1, 0)) % n);
    float hD = height((p - ivec2(0, 1) + n) % n);
    float hU = height((p + ivec2(0, 1)) % n);
#else
    ivec2 hi = textureSize(u_field, 0) - 1;
    float hL = height(clamp(p - ivec2(1, 0), ivec2(0), hi));
    float hR = height(clamp(p + ivec2(1, 0), ivec2(0), hi));
    float hD = height(clamp(p - ivec2(0, 1), ivec2(0), hi));
    float hU = height(clamp(p + ivec2(0, 1), ivec2(0), hi));
#endif
    o_surface = vec4(encode_surface(vec3(height(p), hL - hR, hD - hU)), 1.0);
}
