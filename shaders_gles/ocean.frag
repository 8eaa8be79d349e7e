#version 300 es
// Open water (REFERENCE.md section 2): the height is an fBm of choppy wave octaves, each travelling in
// two directions and rotated 45 degrees from the last; the view ray marches that height field; the hit is
// lit by a sun, a warm back light and the sky dome, with a Fresnel reflection of the sky.
//   OCEAN_SECANT (ocean.method = "secant", the default): the ray is bracketed between the plane of the
//                highest crest and the sea's floor (no wave is lower than 0), stepped coarsely to the
//                first point under the water, then refined by secant steps on a height of
//                GEOMETRY_OCTAVES octaves (after the height-map tracing of Alexander Alekseev's
//                "Seascape", Shadertoy 2014); the normal takes every octave. At most twelve height reads a
//                pixel, and none for a ray above the highest wave.
//   otherwise ("reference"): the reference's march of up to 200 steps on the full height.
precision highp float;
precision highp int;

#include "hash.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

uniform vec3 u_cam_forward;
uniform vec3 u_cam_right;
uniform vec3 u_cam_up;
uniform vec2 u_cam_scale;      // tan(fov / 2) * (aspect, 1), of the whole view (v_uv spans it)

uniform vec3 u_ocean_camera_position;
uniform vec3 u_ocean_sea_color;
uniform float u_ocean_choppiness;
uniform int u_ocean_octaves;
uniform float u_ocean_height;

const int MAX_OCTAVES = 8;  // ocean.octaves' maximum
const int MARCH_STEPS = 200;
const float MARCH_EPSILON = 1e-4;
const float NORMAL_EPSILON = 1e-3;
const float FAR = 400.0;
const vec3 SUN = vec3(0.57735027);  // normalize(1, 1, 1)
const vec3 BACK_LIGHT = vec3(0.52, 0.42, 0.34);
const mat2 OCTAVE_ROTATION = mat2(0.70710678, 0.70710678, -0.70710678, 0.70710678);  // 45 degrees

// Per octave, how far time has moved its two travelling terms, computed on the CPU in double
// (systems/ocean/ocean_system.hpp), so the sea is continuous and precise for as long as the display runs:
// u_octave_shift is (fraction of a noise cell, sine phase modulo pi) of the forward term, then of the
// backward one; u_octave_cells the whole noise cells of each (the bits of a uint).
uniform vec4 u_octave_shift[MAX_OCTAVES];
uniform ivec2 u_octave_cells[MAX_OCTAVES];

// One choppy octave at q, moved by time: offset by noise of itself, then sharpen the crests by the
// choppiness power. The noise moves by cells + fraction; |sin| and |cos| repeat every pi, so they move
// by the phase alone.
float choppy_wave(vec2 q, int cells, float fraction, float phase, float choppy) {
    vec2 uv = q + phase + scrolled_value_noise(q + fraction, ivec2(cells), 7u) * 2.0 - 1.0;
    vec2 a = 1.0 - abs(sin(uv));
    vec2 b = abs(cos(uv));
    vec2 s = mix(a, b, a);
    return pow(1.0 - sqrt(s.x * s.y), choppy);
}

float sea_height(vec2 p, int octaves) {
    float frequency = 0.16;
    float amplitude = u_ocean_height;
    float choppy = u_ocean_choppiness;
    vec2 uv = p;
    float h = 0.0;
    for (int i = 0; i < MAX_OCTAVES; ++i) {
        if (i >= octaves) break;
        // The reference's (uv + t) * frequency and (uv - 0.8 t) * frequency, with t's part from the CPU.
        vec2 q = uv * frequency;
        vec4 shift = u_octave_shift[i];
        float d = choppy_wave(q, u_octave_cells[i].x, shift.x, shift.y, choppy) +
                  choppy_wave(q, u_octave_cells[i].y, shift.z, shift.w, choppy);
        h += d * amplitude;
        uv = OCTAVE_ROTATION * uv + vec2(100.0, 0.0);
        frequency *= 2.0;
        amplitude *= 0.22;
        choppy = mix(choppy, 1.0, 0.2);
    }
    return h;
}

vec3 sky(vec3 dir) { return mix(vec3(0.58, 0.77, 1.0), vec3(1.0), clamp(1.5 * dir.y, 0.0, 1.0)); }

vec3 sea_normal(vec3 p) {
    float h = sea_height(p.xz, u_ocean_octaves);
    float hx = sea_height(p.xz + vec2(NORMAL_EPSILON, 0.0), u_ocean_octaves);
    float hz = sea_height(p.xz + vec2(0.0, NORMAL_EPSILON), u_ocean_octaves);
    return normalize(vec3(h - hx, NORMAL_EPSILON, h - hz));
}

#ifdef OCEAN_SECANT
const int GEOMETRY_OCTAVES = 4;
const int COARSE_STEPS = 6;
const int SECANT_STEPS = 5;

// The highest a crest can reach: each octave's two terms are at most 1 apiece, times its amplitude.
float highest_wave() {
    float sum = 0.0, amplitude = u_ocean_height;
    for (int i = 0; i < MAX_OCTAVES; ++i) {
        if (i >= u_ocean_octaves) break;
        sum += 2.0 * amplitude;
        amplitude *= 0.22;
    }
    return sum;
}

// The gap between the ray at t and the sea under it (positive above the water).
float gap_at(vec3 origin, vec3 dir, float t, int octaves) {
    vec3 p = origin + dir * t;
    return p.y - sea_height(p.xz, octaves);
}

// The distance along the ray to the sea, or -1 for a ray that meets none within FAR: COARSE_STEPS steps,
// closer together near the eye, find the first one under the water (so a grazing ray mostly meets the
// nearer crest; a crest thinner than a step can still be passed), then secant steps refine it between
// that step and the one before. An eye under a crest's height meets the water where it starts.
float march(vec3 origin, vec3 dir) {
    if (dir.y >= -1e-4) return -1.0;
    float t_near = max((origin.y - highest_wave()) / -dir.y, 0.0), t_far = min(origin.y / -dir.y, FAR);
    if (t_near >= t_far) return -1.0;
    int octaves = min(GEOMETRY_OCTAVES, u_ocean_octaves);
    float t0 = t_near, g0 = gap_at(origin, dir, t_near, octaves);
    if (g0 < 0.0) return t_near;  // the eye is below the highest crest, and under this one
    float t1 = -1.0, g1 = 0.0;
    for (int i = 1; i <= COARSE_STEPS; ++i) {
        float f = float(i) / float(COARSE_STEPS);
        float t = mix(t_near, t_far, f * f);
        float g = gap_at(origin, dir, t, octaves);
        if (g < 0.0) {
            t1 = t;
            g1 = g;
            break;
        }
        t0 = t;
        g0 = g;
    }
    if (t1 < 0.0) return -1.0;  // still above the water at FAR
    float t = t0;
    for (int i = 0; i < SECANT_STEPS; ++i) {
        t = mix(t0, t1, g0 / max(g0 - g1, 1e-6));
        float g = gap_at(origin, dir, t, octaves);
        if (g < 0.0) {
            t1 = t;
            g1 = g;
        } else {
            t0 = t;
            g0 = g;
        }
    }
    return t;
}
#else
// Marches p.y - height(p.xz) along the ray; returns the distance, or -1 for a ray that meets no water.
float march(vec3 origin, vec3 dir) {
    float t = 0.0;
    for (int i = 0; i < MARCH_STEPS; ++i) {
        vec3 p = origin + dir * t;
        float gap = p.y - sea_height(p.xz, u_ocean_octaves);
        if (gap < MARCH_EPSILON) return t;
        t += clamp(gap, 0.01, 2.0);
        if (t > FAR) break;
    }
    return -1.0;
}
#endif

vec3 sea_color(vec3 p, vec3 n, vec3 view) {
    float diffuse = max(dot(n, SUN), 0.0) * 1.2;
    float back = max(dot(n, normalize(vec3(-SUN.x, 0.0, -SUN.z))), 0.0);
    float dome = (0.2 + 0.8 * n.y) * 0.1;
    vec3 body = u_ocean_sea_color * (diffuse + dome) + u_ocean_sea_color * BACK_LIGHT * back;
    // Fresnel-Schlick, IOR 1.333 as in section 1.
    float f0 = 0.02;
    float fresnel = f0 + (1.0 - f0) * pow(1.0 - abs(dot(n, -view)), 5.0);
    return mix(body, sky(reflect(view, n)), fresnel);
}

void main() {
    vec2 ndc = v_uv * 2.0 - 1.0;
    vec3 dir = normalize(u_cam_forward + ndc.x * u_cam_scale.x * u_cam_right + ndc.y * u_cam_scale.y * u_cam_up);
    vec3 origin = u_ocean_camera_position;
    vec3 color = sky(dir);
    float t = dir.y < 0.0 ? march(origin, dir) : -1.0;
    if (t > 0.0) {
        vec3 p = origin + dir * t;
        vec3 water = sea_color(p, sea_normal(p), dir);
        // Far water fades into the sky: crests smaller than a pixel would only shimmer.
        color = mix(water, color, smoothstep(0.3 * FAR, FAR, t));
    }
    o_color = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
}
