#version 300 es
// Folds what the render pass needs from the height field into one filterable texel per field texel:
// height and its central differences one texel apart (hL - hR, hD - hU). Filtering these linearly equals
// differencing linearly filtered heights, so the render pass takes one fetch where it would take five.
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
    ivec2 hi = textureSize(u_field, 0) - 1;
    float hL = height(clamp(p - ivec2(1, 0), ivec2(0), hi));
    float hR = height(clamp(p + ivec2(1, 0), ivec2(0), hi));
    float hD = height(clamp(p - ivec2(0, 1), ivec2(0), hi));
    float hU = height(clamp(p + ivec2(0, 1), ivec2(0), hi));
    o_surface = vec4(encode_surface(vec3(height(p), hL - hR, hD - hU)), 1.0);
}
