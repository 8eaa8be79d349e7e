#version 300 es
// A rainy street (REFERENCE.md section 3), drawn in screen space: an overcast sky of drifting value-noise
// clouds with lightning; below the horizon a perspective ground with procedural puddles that mirror the
// sky, expanding ripples that brighten the water and bend its reflection, splashes; then horizon fog, a
// colour shift, vignette and the final curve. The rain streaks are the rain overlay (rain_streaks.frag).
precision highp float;
precision highp int;

#include "hash.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

uniform float u_aspect;    // width / height of the whole view (a whole video wall)

uniform vec3 u_street_sky_dark;
uniform vec3 u_street_sky_light;
uniform float u_street_cloud_drift;
uniform float u_street_lightning;
uniform float u_street_horizon;
uniform float u_street_ground_drift;
uniform int u_street_ripples;
uniform float u_street_ripple_speed;
uniform float u_street_ripple_refraction;
uniform int u_street_splashes;
uniform float u_street_splash_speed;
uniform vec3 u_street_water_tint;
uniform float u_street_wet_reflection;
uniform vec3 u_street_fog_color;
uniform float u_street_vignette;
uniform float u_street_color_shift;
uniform vec3 u_street_shift_color;
uniform float u_street_gamma;

const int MAX_SOURCES = 32;
const vec3 FLASH_COLOR = vec3(0.4, 0.45, 0.55);

// Time arrives only as phases and offsets computed on the CPU in double, each modulo the period its term
// repeats at (systems/street/street_system.hpp), so the street is continuous however long the display runs.
uniform vec2 u_lightning_phase;         // radians: 1.7 t + 3 and 2.3 t, modulo 2 pi
// Drifts of the scrolled noises, split into whole lattice cells (the bits of a uint) and a fraction:
uniform float u_cloud_shift[5];         // per cloud octave, sideways: fraction of a cell
uniform int u_cloud_cells[5];           // and whole cells
uniform vec3 u_noise_shift;            // toward the viewer, of the puddle, puddle detail and asphalt noises
uniform int u_noise_cells[3];
uniform float u_ripple_age[MAX_SOURCES];  // per source: seconds into its current repeat
uniform int u_ripple_repeat[MAX_SOURCES];  // which repeat (the bits of a uint): where it falls
uniform float u_splash_age[MAX_SOURCES];
uniform int u_splash_repeat[MAX_SOURCES];

// The clouds: five octaves of noise, each scrolled sideways by its own drift.
float fbm(vec2 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int i = 0; i < 5; ++i) {
        sum += amplitude * scrolled_value_noise(p + vec2(u_cloud_shift[i], 0.0), ivec2(u_cloud_cells[i], 0), uint(i) + 11u);
        p = p * 2.03 + vec2(17.0, 9.0);
        amplitude *= 0.5;
    }
    return sum / 0.96875;  // 0..1
}

float lightning() {
    float f = sin(u_lightning_phase.x) * sin(u_lightning_phase.y);
    return clamp((f - 0.98) / 0.02, 0.0, 1.0) * u_street_lightning;
}

vec3 sky(vec2 uv) {
    vec2 p = vec2(uv.x * u_aspect, uv.y) * 3.0;
    return mix(u_street_sky_dark, u_street_sky_light, fbm(p)) + FLASH_COLOR * lightning();
}

// Screen point below the horizon -> ground coordinates (perspective: x / depth, 1 / depth). The ground's
// drift toward the viewer moves only its noise (u_noise_shift): ripples and splashes ride along with it,
// so their distances do not change.
vec2 ground_of(vec2 uv) {
    float depth = max((u_street_horizon - uv.y) / u_street_horizon, 1e-3);
    return vec2((uv.x - 0.5) * u_aspect / depth, 1.0 / depth) * 0.3;
}

// Where a repeating source falls in its repeat `repeat`: a random screen spot below the horizon, so it
// is always in view. Its period, phase and repeat come from the CPU (street_system.cpp).
vec2 source_spot(int i, int repeat, uint salt) {
    uint id = uint(i);
    vec2 spot = vec2(unit_float(hash3(id, uint(repeat), salt + 2u)),
                     unit_float(hash3(id, uint(repeat), salt + 3u)) * u_street_horizon * 0.9);
    return ground_of(spot);
}

float ring(float d, float radius, float width) { return 1.0 - smoothstep(0.0, width, abs(d - radius)); }

float ripples(vec2 g) {
    float sum = 0.0;
    for (int i = 0; i < MAX_SOURCES; ++i) {
        if (i >= u_street_ripples) break;
        float age = u_ripple_age[i];
        float d = distance(g, source_spot(i, u_ripple_repeat[i], 101u));
        float r = u_street_ripple_speed * age;
        float rings = ring(d, r, 0.008) + 0.5 * ring(d, 0.7 * r, 0.008);
        sum += rings * exp(-1.5 * age) * smoothstep(0.0, 0.3, age);
    }
    return sum;
}

float splashes(vec2 g) {
    float sum = 0.0;
    for (int i = 0; i < MAX_SOURCES; ++i) {
        if (i >= u_street_splashes) break;
        float age = u_splash_age[i];
        sum += ring(distance(g, source_spot(i, u_splash_repeat[i], 211u)), u_street_splash_speed * age, 0.006) *
               exp(-4.0 * age);
    }
    return sum;
}

void main() {
    vec2 uv = v_uv;
    vec3 color;
    if (uv.y >= u_street_horizon) {
        color = sky(uv);
    } else {
        vec2 g = ground_of(uv);
        float outline = scrolled_value_noise(4.0 * g + 0.5 + vec2(0.0, u_noise_shift.x), ivec2(0, u_noise_cells[0]), 3u);
        float detail = scrolled_value_noise(8.0 * g + 10.0 + vec2(0.0, u_noise_shift.y), ivec2(0, u_noise_cells[1]), 5u);
        float puddle = smoothstep(0.42, 0.55, outline + 0.3 * detail);
        float ripple = ripples(g) * puddle;
        // The reflection: the sky at the mirrored screen point, bent by the ripples.
        vec2 mirrored = vec2(uv.x, 2.0 * u_street_horizon - uv.y) + ripple * u_street_ripple_refraction;
        vec3 reflection = sky(mirrored) * 1.3 + u_street_water_tint;
        vec3 asphalt = vec3(0.05, 0.05, 0.06) *
                       (0.7 + 0.6 * scrolled_value_noise(40.0 * g + vec2(0.0, u_noise_shift.z), ivec2(0, u_noise_cells[2]), 9u));
        color = mix(asphalt, reflection, mix(u_street_wet_reflection, 1.0, puddle));
        color += vec3(0.25, 0.27, 0.3) * ripple + vec3(0.5) * splashes(g);
    }
    float fog = exp(-abs(uv.y - u_street_horizon) * 12.0);
    color = mix(color, u_street_fog_color, fog);
    color = mix(color, color * u_street_shift_color, u_street_color_shift);
    color *= 1.0 - u_street_vignette * length(uv - 0.5);
    o_color = vec4(pow(max(color, 0.0), vec3(u_street_gamma)), 1.0);
}
