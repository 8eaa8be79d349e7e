#version 300 es
// A rainy street (REFERENCE.md section 3), drawn in screen space: an overcast sky of drifting value-noise
// clouds with lightning; below the horizon a perspective ground with procedural puddles that mirror the
// sky, expanding ripples that brighten the water and bend its reflection, splashes; then horizon fog, a
// colour shift, vignette and the final curve. The rain streaks are the rain overlay (rain_streaks.frag).
precision highp float;
precision highp int;

#include "hash.glsl"

in vec2 v_uv;
out vec4 o_color;

uniform float u_time;      // seconds, wrapped on the CPU to keep float precision
uniform float u_aspect;    // width / height
uniform int u_seed;

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

float fbm(vec2 p) {
    float sum = 0.0, amplitude = 0.5;
    for (int i = 0; i < 5; ++i) {
        sum += amplitude * value_noise(p, uint(i) + 11u);
        p = p * 2.03 + vec2(17.0, 9.0);
        amplitude *= 0.5;
    }
    return sum / 0.96875;  // 0..1
}

float lightning() {
    float f = sin(1.7 * u_time + 3.0) * sin(2.3 * u_time);
    return clamp((f - 0.98) / 0.02, 0.0, 1.0) * u_street_lightning;
}

vec3 sky(vec2 uv) {
    vec2 p = vec2(uv.x * u_aspect + u_time * u_street_cloud_drift, uv.y) * 3.0;
    return mix(u_street_sky_dark, u_street_sky_light, fbm(p)) + FLASH_COLOR * lightning();
}

// Screen point below the horizon -> ground coordinates (perspective: x / depth, 1 / depth).
vec2 ground_of(vec2 uv) {
    float depth = max((u_street_horizon - uv.y) / u_street_horizon, 1e-3);
    return vec2((uv.x - 0.5) * u_aspect / depth, 1.0 / depth) * 0.3 + vec2(0.0, u_time * u_street_ground_drift);
}

// A repeating source: its age in this repeat and its ground position, both from integer hashes.
// Sources sit at random screen spots below the horizon, so they are always in view.
void source_at(int i, uint salt, float min_period, float max_period, out float age, out vec2 where) {
    uint id = uint(i);
    float period = mix(min_period, max_period, unit_float(hash3(id, salt, uint(u_seed))));
    float s = u_time / period + unit_float(hash3(id, salt + 1u, uint(u_seed)));
    uint repeat = uint(int(floor(s)));
    age = fract(s) * period;
    vec2 spot = vec2(unit_float(hash3(id, repeat, salt + 2u)),
                     unit_float(hash3(id, repeat, salt + 3u)) * u_street_horizon * 0.9);
    where = ground_of(spot);
}

float ring(float d, float radius, float width) { return 1.0 - smoothstep(0.0, width, abs(d - radius)); }

float ripples(vec2 g) {
    float sum = 0.0;
    for (int i = 0; i < MAX_SOURCES; ++i) {
        if (i >= u_street_ripples) break;
        float age;
        vec2 where;
        source_at(i, 101u, 2.5, 4.5, age, where);
        float d = distance(g, where);
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
        float age;
        vec2 where;
        source_at(i, 211u, 1.0, 2.5, age, where);
        sum += ring(distance(g, where), u_street_splash_speed * age, 0.006) * exp(-4.0 * age);
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
        float puddle = smoothstep(0.42, 0.55, value_noise(4.0 * g + 0.5, 3u) + 0.3 * value_noise(8.0 * g + 10.0, 5u));
        float ripple = ripples(g) * puddle;
        // The reflection: the sky at the mirrored screen point, bent by the ripples.
        vec2 mirrored = vec2(uv.x, 2.0 * u_street_horizon - uv.y) + ripple * u_street_ripple_refraction;
        vec3 reflection = sky(mirrored) * 1.3 + u_street_water_tint;
        vec3 asphalt = vec3(0.05, 0.05, 0.06) * (0.7 + 0.6 * value_noise(40.0 * g, 9u));
        color = mix(asphalt, reflection, mix(u_street_wet_reflection, 1.0, puddle));
        color += vec3(0.25, 0.27, 0.3) * ripple + vec3(0.5) * splashes(g);
    }
    float fog = exp(-abs(uv.y - u_street_horizon) * 12.0);
    color = mix(color, u_street_fog_color, fog);
    color = mix(color, color * u_street_shift_color, u_street_color_shift);
    color *= 1.0 - u_street_vignette * length(uv - 0.5);
    o_color = vec4(pow(max(color, 0.0), vec3(u_street_gamma)), 1.0);
}
