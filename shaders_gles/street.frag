#version 300 es
// A rainy street at night (REFERENCE.md section 3), drawn in screen space: an overcast sky of drifting
// value-noise clouds with lightning, lit orange from below by the city; below the horizon a perspective
// ground with procedural puddles, expanding ripples that brighten the water and bend its reflection,
// splashes; then horizon fog, a colour shift, vignette and the final curve (the reference's). Around it
// the street: facades on both sides with lit windows and shop fronts, a row of street lamps down each
// kerb with their glow, the pools they light, and their reflections, long streaks on the wet asphalt and
// sharper in the puddles, which also mirror the facades. The rain streaks are the rain overlay
// (rain_streaks.frag).
//
// The eye (what ground_of's mapping is): a pinhole of focal length 1 in screen units (the view's height is
// 1; X = (uv.x - 0.5) * aspect, Y = uv.y - horizon) at the height EYE = 0.3 * street.horizon over the
// ground, looking level down the street: a point (x, y, z) shows at X = x / z, Y = (y - EYE) / z. A unit
// is about 13 m (an eye 1.6 m high).
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
uniform int u_street_lamps;
uniform float u_street_lit_windows;

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
// Per ripple and splash source, worked out on the CPU for its current repeat (street_system.hpp's
// street_sources): where it falls on the ground (a random screen spot below the horizon, so it is always
// in view), its ring's radius now, and its strength now.
uniform vec4 u_ripple[MAX_SOURCES];
uniform vec4 u_splash[MAX_SOURCES];
// The street's drift toward the viewer (street.ground_drift) in its own units: a fraction and whole units
// (the bits of a uint). The facades and lamps move with the puddles.
uniform float u_drift_shift;
uniform int u_drift_cells;
// Per lamp of a row, nearest first (systems/street/street_system.hpp's street_lamps): its distance z down
// the street, 1 / z, the square of its glow's size (0.006 / z), and how much it shows (it fades in at the
// far end of the row and out by the eye, so none pops as the street drifts).
const int MAX_LAMPS = 16;  // street.lamps' maximum
uniform vec4 u_lamp[MAX_LAMPS];

const float FACADE = 0.6;         // half the street's width, kerb to kerb plus the pavements (units)
const float KERB = 0.46;          // where the pavement starts
const float BLOCK = 0.5;          // a building's frontage: two to a unit
const float FLOOR = 0.25;         // a storey
const float BAY = 0.125;          // a window bay, four to a building
const float LAMP_HEIGHT = 0.42;
const float LAMP_X = 0.48;        // the lamps stand at the kerb, one a unit down each side
const vec3 LAMP_COLOR = vec3(1.0, 0.72, 0.42);  // sodium-warm
const vec3 CITY_GLOW = vec3(0.20, 0.11, 0.05);   // the clouds lit from below
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
    float clouds = fbm(p);
    vec3 glow = CITY_GLOW * exp(-3.0 * max(uv.y - u_street_horizon, 0.0)) * (0.5 + clouds);
    return mix(u_street_sky_dark, u_street_sky_light, clouds) * 0.6 + glow + FLASH_COLOR * lightning();
}

float eye_height() { return 0.3 * u_street_horizon; }

// The low bytes of a hash as independent 0..1 values (unit_float takes its top 24 bits): byte 0 or 1.
float byte_float(uint h, uint byte) { return float((h >> (8u * byte)) & 255u) / 255.0; }

// How much of the rain's haze lies between the eye and a point z units down the street.
float distance_fog(float z) { return 1.0 - exp(-0.12 * z); }

// A facade's colour at distance z down the street (units, before the drift) and height y on the side
// `side` (-1 left, 1 right), or alpha 0 above its roof: a dark wall with a storey of windows every
// FLOOR, a quarter of them lit (street.lit_windows) in warm or cool light, each its own brightness, and a
// row of shop fronts at street level. `blur` (units of z a pixel spans) fades the windows to their mean
// where they would alias.
vec4 facade(float z, float y, float side, float blur) {
    float zz = z + u_drift_shift;  // the drift: whole units in u_drift_cells
    uint block = uint(int(floor(zz / BLOCK))) + uint(u_drift_cells) * 2u;
    uint salt = side > 0.0 ? 31u : 37u;
    // One hash a building, one a window: their bytes choose the rest.
    uint building = hash3(block, salt, 1u);
    float top = FLOOR * (3.0 + floor(9.0 * unit_float(building)));
    if (y > top) return vec4(0.0);
    vec3 wall = vec3(0.035, 0.035, 0.04) * (0.6 + 0.8 * byte_float(building, 0u));
    float along = fract(zz / BAY), up = fract(y / FLOOR);
    uint bay = uint(int(floor(zz / BAY))) + uint(u_drift_cells) * 8u;
    uint storey = uint(int(floor(y / FLOOR)));
    float pane = step(0.3, along) * step(along, 0.7) * step(0.3, up) * step(up, 0.78);
    vec3 light;
    if (storey == 0u) {  // shop fronts: wide, mostly lit, warm
        float shop = step(0.08, along) * step(along, 0.92) * step(0.12, up) * step(up, 0.62);
        uint front = hash3(bay / 2u, salt, 5u);
        float lit = step(unit_float(front), 0.75);
        float kind = byte_float(front, 0u);
        vec3 tone = kind < 0.65 ? vec3(1.0, 0.7, 0.4)         // warm: a cafe, a shop
                    : kind < 0.8 ? vec3(0.8, 0.9, 1.0)       // cool white: a pharmacy, a late shop
                    : kind < 0.92 ? vec3(0.2, 0.9, 0.8)      // a teal sign's light
                                  : vec3(1.0, 0.3, 0.5);     // a red-pink one
        // Brighter toward the ceiling, each front its own brightness.
        float bright = (0.5 + 0.7 * byte_float(front, 1u)) * (0.35 + 0.9 * up * up);
        light = tone * bright * lit * shop;
        pane = shop;
    } else {
        uint window = hash3(bay, storey, salt);
        float lit = step(unit_float(window), u_street_lit_windows);
        vec3 tone = mix(vec3(1.0, 0.74, 0.45), vec3(0.65, 0.78, 1.0), step(0.7, byte_float(window, 0u)));
        light = tone * (0.35 + 0.65 * byte_float(window, 1u)) * lit * pane;
    }
    vec3 mean = storey == 0u ? vec3(0.35, 0.28, 0.2) : vec3(0.55, 0.48, 0.4) * 0.17 * u_street_lit_windows;
    float fade = smoothstep(0.3, 1.0, blur / BAY);
    vec3 c = wall * (1.0 - 0.5 * pane) + mix(light, mean, fade);
    return vec4(c, 1.0);
}

// The glow of a light at screen point `at` (X, Y), the square of its size across s2, seen from screen point p; `stretch`
// draws it out vertically (a reflection in rough wet asphalt).
float glow(vec2 p, vec2 at, float s2, float stretch) {
    vec2 d = (p - at) / vec2(1.0, stretch);
    float r2 = dot(d, d);
    return s2 / (r2 + s2) + 80.0 * s2 / (r2 + 400.0 * s2);
}

// The lamps down both sides and, mirrored in the wet ground, their reflections (stretch > 1 on rough
// asphalt, near 1 in a puddle), as seen at screen point p. The two rows mirror each other about the
// street's middle, so each lamp is taken on p's side (|X|): the far row's glow there is under 1%.
vec3 lamps(vec2 p, bool reflected, float stretch) {
    float sum = 0.0, poles = 0.0;
    float eye = eye_height();
    float head = (reflected ? -LAMP_HEIGHT : LAMP_HEIGHT) - eye;
    vec2 q = vec2(abs(p.x), p.y);
    for (int i = 0; i < MAX_LAMPS; ++i) {
        if (i >= u_street_lamps) break;
        vec4 lamp = u_lamp[i];  // z, 1 / z, the glow's size squared, how much it shows
        vec2 at = vec2(LAMP_X, head) * lamp.y;
        sum += glow(q, at, lamp.z, stretch) * lamp.w;
        if (!reflected)  // its pole, a dark line from the ground up to the head
            poles += step(abs(q.x - at.x), 0.003 * lamp.y) * step(-eye * lamp.y, q.y) * step(q.y, at.y) * lamp.w;
    }
    return LAMP_COLOR * 1.5 * sum * (reflected ? 0.6 : 1.0) - vec3(0.05) * poles;
}

// What the eye sees up the ray through screen point p = (X, Y): a facade where the ray meets one below
// its roof, the sky (at sky_uv) beyond. A ray reflected in the ground is the ray through the mirrored
// point (X, -Y): it rises as far above the eye's height as the direct one falls below it.
vec3 city(vec2 p, vec2 sky_uv) {
    // The pixel's footprint across, taken here in uniform control flow: GLSL ES leaves derivatives
    // undefined inside a branch that neighbouring pixels may not take.
    float across = fwidth(p.x);
    float side = p.x < 0.0 ? -1.0 : 1.0;
    float z = FACADE / max(abs(p.x), 1e-4);
    float y = eye_height() + p.y * z;
    vec4 wall = y > 0.0 ? facade(z, y, side, z * z / FACADE * across) : vec4(0.0);
    // The haze: by distance on a facade, and on the open sky by how near the horizon it is (the
    // reference's fog).
    if (wall.a > 0.0) return mix(wall.rgb, u_street_fog_color * 0.7, distance_fog(z));
    return mix(sky(sky_uv), u_street_fog_color, exp(-abs(sky_uv.y - u_street_horizon) * 12.0));
}

// Screen point below the horizon -> ground coordinates (perspective: x / depth, 1 / depth). The ground's
// drift toward the viewer moves only its noise (u_noise_shift): ripples and splashes ride along with it,
// so their distances do not change.
vec2 ground_of(vec2 uv) {
    float depth = max((u_street_horizon - uv.y) / u_street_horizon, 1e-3);
    return vec2((uv.x - 0.5) * u_aspect / depth, 1.0 / depth) * 0.3;
}

float ring(float d, float radius, float width) { return 1.0 - smoothstep(0.0, width, abs(d - radius)); }

float ripples(vec2 g) {
    float sum = 0.0;
    for (int i = 0; i < MAX_SOURCES; ++i) {
        if (i >= u_street_ripples) break;
        vec4 source = u_ripple[i];  // where (ground), its ring's radius, its strength
        float d = distance(g, source.xy);
        float rings = ring(d, source.z, 0.008) + 0.5 * ring(d, 0.7 * source.z, 0.008);
        sum += rings * source.w;
    }
    return sum;
}

float splashes(vec2 g) {
    float sum = 0.0;
    for (int i = 0; i < MAX_SOURCES; ++i) {
        if (i >= u_street_splashes) break;
        vec4 source = u_splash[i];
        sum += ring(distance(g, source.xy), source.z, 0.006) * source.w;
    }
    return sum;
}

void main() {
    vec2 uv = v_uv;
    vec2 p = vec2((uv.x - 0.5) * u_aspect, uv.y - u_street_horizon);
    float eye = eye_height();
    // The ground under the ray, or none (above the horizon, or a facade is nearer).
    float ground_z = p.y < 0.0 ? eye / -p.y : 1e9;
    float wall_z = FACADE / max(abs(p.x), 1e-4);
    bool ground = ground_z <= wall_z;
    // On the ground: the puddles, and the ripples that bend the reflection.
    vec2 g = vec2(0.0);
    float puddle = 0.0, ripple = 0.0;
    if (ground) {
        g = ground_of(uv);
        float outline = scrolled_value_noise(4.0 * g + 0.5 + vec2(0.0, u_noise_shift.x), ivec2(0, u_noise_cells[0]), 3u);
        float detail = scrolled_value_noise(8.0 * g + 10.0 + vec2(0.0, u_noise_shift.y), ivec2(0, u_noise_cells[1]), 5u);
        puddle = smoothstep(0.42, 0.55, outline + 0.3 * detail);
        ripple = ripples(g) * puddle;
    }
    // What the ray meets up the street, the facades or the sky, and the lamps: straight on, or for the
    // ground up the mirrored ray, bent by the ripples (one call for either, so each is worked out once).
    float bend = ripple * u_street_ripple_refraction;
    vec2 seen_uv = ground ? vec2(uv.x, 2.0 * u_street_horizon - uv.y) + bend : uv;
    vec2 seen = vec2((seen_uv.x - 0.5) * u_aspect, seen_uv.y - u_street_horizon);
    vec3 city_light = city(seen, seen_uv);
    // The lamps' reflections: long on the asphalt, short in the puddles.
    vec3 lamp_light = lamps(ground ? vec2(seen.x, -seen.y) : p, ground, ground ? mix(9.0, 2.0, puddle) : 1.0);
    vec3 color = city_light + lamp_light;
    if (ground) {
        vec3 reflection = city_light * 1.3 + u_street_water_tint;
        float pavement = step(KERB, abs(g.x));
        vec3 asphalt = vec3(0.05, 0.05, 0.06) * (1.0 + 0.5 * pavement) *
                       (0.7 + 0.6 * scrolled_value_noise(40.0 * g + vec2(0.0, u_noise_shift.z), ivec2(0, u_noise_cells[2]), 9u));
        asphalt *= 1.0 - 0.5 * (1.0 - smoothstep(0.0, 0.01, abs(abs(g.x) - KERB)));  // the kerb's edge
        float wet = mix(u_street_wet_reflection, 1.0, puddle);
        color = mix(asphalt, reflection, wet);
        // The lamps' light on the ground below them.
        float pool = 0.0, dx = LAMP_X - abs(g.x);
        for (int i = 0; i < MAX_LAMPS; ++i) {
            if (i >= u_street_lamps) break;
            float dz = g.y - u_lamp[i].x;
            pool += u_lamp[i].w / (1.0 + 60.0 * (dx * dx + dz * dz));
        }
        color += LAMP_COLOR * 0.08 * pool * (1.0 - 0.6 * puddle);
        color += lamp_light * mix(0.8, 1.2, puddle);
        color += vec3(0.25, 0.27, 0.3) * ripple + vec3(0.5) * splashes(g);
        color = mix(color, u_street_fog_color * 0.7, distance_fog(ground_z));
    }
    color = mix(color, color * u_street_shift_color, u_street_color_shift);
    color *= 1.0 - u_street_vignette * length(uv - 0.5);
    o_color = vec4(pow(max(color, 0.0), vec3(u_street_gamma)), 1.0);
}
