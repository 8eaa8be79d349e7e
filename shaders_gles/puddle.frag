#version 300 es
// The puddle image (REFERENCE.md section 1): a box of water whose top is displaced by the wave field, seen from
// the camera; Fresnel-Schlick between a rotated environment reflection and the ground refracted through
// murky water; then fog, vignette, tone mapping and sRGB encoding.
//
// Two ways to find where a view ray meets the water, chosen by #define:
//   METHOD_RAYMARCH: the reference's sphere-trace of the displaced box (render.march_steps reads);
//   otherwise:       meet the flat top analytically, then refine twice against the height (2 reads).
// The displacement is tiny next to the box, so both find the same point (a test compares the pictures).
precision highp float;

#include "surface_encoding.glsl"
#include "colour.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform sampler2D u_surface;   // height, hL - hR, hD - hU (surface.frag)
uniform samplerCube u_env;     // linear radiance: sRGB8 decoded by the sampler, half float, or RGBM (u_env_rgbm)
uniform sampler2D u_ground;    // sRGB: sampled as linear

// Camera, computed once per frame on the CPU.
uniform vec3 u_camera_position;
uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;      // tan(fov / 2) * (aspect, 1)
uniform mat3 u_env_matrix;     // rotation about +Y by environment.rotation
uniform bool u_env_rgbm;       // the cube holds RGBM texels (no half-float render targets)
uniform float u_env_scale;     // 2^environment.exposure

// Parameters, named after the registry (params.def).
uniform vec3 u_puddle_size;
uniform float u_puddle_depth;
uniform float u_wave_height_scale;
uniform float u_water_normal_strength;
uniform float u_water_reflectivity;
uniform float u_water_turbidity;
uniform vec3 u_water_tint;
uniform bool u_ground_checkerboard;
uniform float u_ground_scale;
uniform float u_look_fog_density;
uniform float u_look_vignette;
uniform int u_render_march_steps;
uniform int u_look_tonemap;    // index into look.tonemap's choices: TONEMAP_* in colour.glsl

const float IOR = 1.333;

vec3 surface_at(vec2 xz) {
    vec2 uv = xz / u_puddle_size.xz + 0.5;
    return decode_surface(texture(u_surface, uv).rgb);
}

float top() { return 0.5 * u_puddle_size.y; }
float water_height(vec2 xz) { return top() + surface_at(xz).r * u_wave_height_scale; }

vec3 environment(vec3 dir) {
    vec4 texel = texture(u_env, u_env_matrix * dir);
    return (u_env_rgbm ? decode_rgbm(texel) : texel.rgb) * u_env_scale;
}

// Slab intersection with the axis-aligned box of half size h, widened upward by the largest displacement.
bool enter_box(vec3 o, vec3 d, vec3 h, out float t_near) {
    vec3 inv = 1.0 / d;
    vec3 t0 = (-h - o) * inv, t1 = (h - o) * inv;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    t_near = max(max(lo.x, lo.y), max(lo.z, 0.0));
    float t_far = min(min(hi.x, hi.y), hi.z);
    return t_near <= t_far;
}

#ifdef METHOD_RAYMARCH
// Distance to the box whose top face is displaced by the water height (a bound, as sphere tracing needs).
float water_sdf(vec3 p) {
    vec3 h = 0.5 * u_puddle_size;
    vec3 q = abs(p) - h;
    q.y = max(p.y - water_height(p.xz), -p.y - h.y);
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

bool hit_water(vec3 o, vec3 d, out vec3 p, out vec3 s) {
    float t;
    vec3 bound = 0.5 * u_puddle_size + vec3(0.0, 4.0 * u_wave_height_scale, 0.0);
    if (!enter_box(o, d, bound, t)) return false;
    for (int i = 0; i < 64; ++i) {
        if (i >= u_render_march_steps) break;
        float dist = water_sdf(o + t * d);
        if (dist < 1e-3) break;
        t += dist;
    }
    p = o + t * d;
    s = surface_at(p.xz);
    return water_sdf(p) < 0.05;
}
#else
bool hit_water(vec3 o, vec3 d, out vec3 p, out vec3 s) {
    if (d.y >= 0.0) return false;
    float t = (top() - o.y) / d.y;
    p = o + t * d;
    if (any(greaterThan(abs(p.xz), 0.5 * u_puddle_size.xz))) return false;
    // The top is displaced by a fraction of a unit: two fixed-point steps land on it. The second step's
    // texel, read a hair from where it lands, also gives the slopes: one surface read fewer per pixel.
    for (int i = 0; i < 2; ++i) {
        s = surface_at(p.xz);
        t = (top() + s.r * u_wave_height_scale - o.y) / d.y;
        p = o + t * d;
    }
    return true;
}
#endif

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

vec3 ground_colour(vec2 xz) {
    vec2 g = xz * u_ground_scale;
    if (u_ground_checkerboard) {
        vec2 tile = floor(g);
        bool light = mod(tile.x + tile.y, 2.0) > 0.5;
        vec3 c = light ? vec3(0.25, 0.22, 0.20) : vec3(0.15, 0.12, 0.10);
        return c + (hash12(floor(xz * 16.0)) - 0.5) * 0.05;  // +-0.025 grain
    }
    return texture(u_ground, g).rgb * 0.6;
}

void main() {
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 o = u_camera_position;
    vec3 d = normalize(u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up);

    vec3 colour;
    vec3 p, s;
    if (hit_water(o, d, p, s)) {
        vec3 n = normalize(vec3(s.g * u_water_normal_strength, 1.0, s.b * u_water_normal_strength));

        const float f0 = ((1.0 - IOR) / (1.0 + IOR)) * ((1.0 - IOR) / (1.0 + IOR));
        float x = 1.0 - abs(dot(d, n));
        float x2 = x * x;
        float fresnel = f0 + (1.0 - f0) * (x2 * x2 * x);  // Schlick's (1 - cos)^5 without pow

        vec3 reflection = environment(reflect(d, n));

        vec3 ground;
        vec3 t = refract(d, n, 1.0 / IOR);
        if (t.y < 0.0) {
            float along = (-u_puddle_depth - p.y) / t.y;  // distance through the water
            ground = ground_colour(p.xz + along * t.xz);
            float visibility = exp(-along * u_water_turbidity);
            ground = mix(u_water_tint, ground, visibility);
            ground *= 0.7 * (1.0 - 0.5 * u_water_tint);
        } else {
            ground = 0.3 * u_water_tint;
        }

        float m = mix(0.3, 0.8, u_water_reflectivity);
        colour = mix(ground, reflection, fresnel * (m - 0.3) + 0.3);
        colour += 0.15 * u_water_tint * (1.0 - fresnel);

        float fog = exp(-distance(o, p) * u_look_fog_density);
        colour = mix(0.7 * colour, colour, fog);
    } else {
        colour = environment(d);  // the sky beyond the puddle: at infinity, unfogged
    }

    colour *= 1.0 - u_look_vignette * length(v_uv - 0.5);
    o_color = vec4(encode_srgb(tonemap(colour, u_look_tonemap)), 1.0);
}
