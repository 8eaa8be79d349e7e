#version 300 es
// One face of the camera environment cube: for each texel's direction, the camera image under the
// chosen mapping, mixed with the static cubemap by environment.camera_blend. Directions are in cube space;
// the puddle pass rotates by environment.rotation when it samples, as it does for the cubemap.
//
// Mappings (docs/camera.md, "Mapping"): the image centre looks along u_axis (toward -X, 35 degrees
// above the horizon: where the default view's reflection looks); image right is u_right, up u_up.
//   MAPPING_MIRROR_BALL: the image's inscribed circle is a mirrored ball seen along -u_axis (a light
//     probe): every direction has a texel, the one straight behind at the rim.
//   otherwise (planar): a perspective window of vertical field of view 2*atan(u_tan_half_fov); beyond
//     its edges the edge texels stretch outward.
precision highp float;

#include "colour.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform samplerCube u_env;      // the static cubemap: linear (sRGB8 decoded by the sampler, half float) or RGBM
uniform bool u_env_rgbm;
uniform sampler2D u_camera;     // the converted camera frame (sRGB: sampled as linear), row 0 at the top
uniform int u_face;             // GL order +X, -X, +Y, -Y, +Z, -Z
uniform vec3 u_axis;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_aspect;         // camera width / height
uniform float u_tan_half_fov;
uniform float u_environment_camera_blend;

// The direction through texel (s, t) of a face, from GL's cube map selection rules.
vec3 face_direction(int face, vec2 st) {
    vec2 ab = st * 2.0 - 1.0;
    if (face == 0) return vec3(1.0, -ab.y, -ab.x);
    if (face == 1) return vec3(-1.0, -ab.y, ab.x);
    if (face == 2) return vec3(ab.x, 1.0, ab.y);
    if (face == 3) return vec3(ab.x, -1.0, -ab.y);
    if (face == 4) return vec3(ab.x, -ab.y, 1.0);
    return vec3(-ab.x, -ab.y, -1.0);
}

vec2 camera_uv(vec3 d) {
#ifdef MAPPING_MIRROR_BALL
    vec3 h = d + u_axis;
    vec3 n = dot(h, h) > 1e-8 ? normalize(h) : u_up;  // straight behind: the rim
    vec2 ball = vec2(dot(n, u_right) / u_aspect, dot(n, u_up));
    return vec2(0.5 + 0.5 * ball.x, 0.5 - 0.5 * ball.y);
#else
    float z = max(dot(d, u_axis), 1e-4);  // behind the camera: far outside, so the edge stretches
    vec2 p = vec2(dot(d, u_right), dot(d, u_up)) / (z * u_tan_half_fov);
    return clamp(vec2(0.5 + 0.5 * p.x / u_aspect, 0.5 - 0.5 * p.y), 0.0, 1.0);
#endif
}

void main() {
    vec3 d = normalize(face_direction(u_face, v_uv));
    vec4 texel = texture(u_env, d);
    vec3 sky = u_env_rgbm ? decode_rgbm(texel) : texel.rgb;  // beyond 1 clips in this 8-bit cube
    vec3 cam = texture(u_camera, camera_uv(d)).rgb;
    o_color = vec4(mix(sky, cam, u_environment_camera_blend), 1.0);
}
