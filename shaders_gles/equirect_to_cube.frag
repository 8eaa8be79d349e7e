#version 300 es
// One face of a cube map from an equirectangular panorama, run once per face at load. The panorama's
// centre looks toward -Z, its right half toward +X, its top row straight up (+Y).
// OUTPUT_RGBM: write RGBM RGBA8 (colour.glsl) where half-float targets are missing.
precision highp float;

#include "colour.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform sampler2D u_panorama;  // rows top first (t = 0 is the top row); sRGB textures decode to linear
uniform int u_face;            // GL order: +X, -X, +Y, -Y, +Z, -Z
uniform float u_face_size;     // texels
uniform vec2 u_panorama_size;  // texels
uniform float u_max_lod;

const float PI = 3.14159265358979;

// The direction GL samples at face coordinates (s, t) in 0..1: the inverse of the major-axis table of
// the GLES 3.0 specification (section 3.8.10). Row 0 of the face is t = 0.
vec3 cube_direction(int face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;  // (sc, tc) / |ma|
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

vec3 panorama(vec3 d, float texel_angle) {
    d = normalize(d);
    float u = 0.5 + atan(d.x, -d.z) / (2.0 * PI);
    float v = 0.5 - asin(clamp(d.y, -1.0, 1.0)) / PI;
    // Rows shrink toward the poles: average about as many panorama texels as this face texel covers,
    // but never more than twice its height across (filtering is isotropic: more would blur the rows).
    float down = texel_angle * u_panorama_size.y / PI;
    float across = texel_angle * u_panorama_size.x / (2.0 * PI) / max(sqrt(1.0 - d.y * d.y), 1e-4);
    float lod = clamp(log2(max(min(across, 2.0 * down), max(down, 1.0))), 0.0, u_max_lod);
    // The sampler repeats (u wraps round at the seam behind, at +Z), but v must not: keep it half a texel
    // of the coarser level read inside the top and bottom rows, or the poles would mix.
    float edge = 0.5 * exp2(ceil(lod)) / u_panorama_size.y;
    v = clamp(v, edge, 1.0 - edge);
    return textureLod(u_panorama, vec2(fract(u), v), lod).rgb;
}

void main() {
    // 2x2 samples per face texel: a panorama wider than four faces is not point-sampled.
    vec2 texel = vec2(1.0 / u_face_size);
    vec2 c = v_uv * 2.0 - 1.0;
    float texel_angle = 2.0 / u_face_size / (1.0 + dot(c, c)) * 0.5;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        vec2 offset = (vec2(float(i & 1), float(i >> 1)) - 0.5) * 0.5 * texel;
        sum += panorama(cube_direction(u_face, v_uv + offset), texel_angle);
    }
    vec3 colour = 0.25 * sum;
#ifdef OUTPUT_RGBM
    o_color = encode_rgbm(colour);
#else
    o_color = vec4(colour, 1.0);
#endif
}
