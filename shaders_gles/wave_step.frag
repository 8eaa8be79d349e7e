#version 300 es
// One step of the damped discrete 2D wave equation (REFERENCE.md section 1):
//   next = 0.5 * (damping * (L + R + D + U - 2 * prev) + disturbance), stored as (next, current).
// Edges clamp, so the border reflects. FIXED_POINT_SCALE selects the RG32I fallback field.
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

uniform float u_wave_damping;
uniform int u_drop_count;
layout(std140) uniform Drops {
    vec4 u_drops[MAX_DROPS];  // x, y in texels; z = strength * activation
};

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
