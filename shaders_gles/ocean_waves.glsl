// The sea's height (REFERENCE.md section 2), shared by the ocean's passes (ocean.frag, which marches it
// per pixel under ocean.method = secant or reference, and ocean_height.frag, which lays it into the height
// map): an fBm of choppy wave octaves, each travelling in two directions and rotated 45 degrees from the
// last. Needs hash.glsl.

uniform float u_ocean_choppiness;
uniform int u_ocean_octaves;
uniform float u_ocean_height;

const int MAX_OCTAVES = 8;  // ocean.octaves' maximum
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

// The height at p (units) of the first `octaves` octaves: 0 (a trough of every term) up to highest_wave().
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

// sea_height band-limited to a footprint of `footprint` units (the ground a map texel covers): an
// octave whose crests come closer than four footprints apart fades out by two (it would only alias, as
// noise in the map), and the slope variance it took with it is added to `lost_variance` (slope squared: its
// amplitude times frequency, times 1.5 for the choppy crests' steeper flanks, squared, per term), for the
// shading to spread the reflection by.
float sea_height_filtered(vec2 p, int octaves, float footprint, out float lost_variance) {
    float frequency = 0.16;
    float amplitude = u_ocean_height;
    float choppy = u_ocean_choppiness;
    vec2 uv = p;
    float h = 0.0;
    lost_variance = 0.0;
    for (int i = 0; i < MAX_OCTAVES; ++i) {
        if (i >= octaves) break;
        float crests = 3.14159265 / frequency;  // |sin| repeats every pi of q
        float kept = smoothstep(2.0, 4.0, crests / footprint);
        float slope = 1.5 * amplitude * frequency;
        lost_variance += 2.0 * (1.0 - kept) * slope * slope;
        if (kept > 0.0) {
            vec2 q = uv * frequency;
            vec4 shift = u_octave_shift[i];
            float d = choppy_wave(q, u_octave_cells[i].x, shift.x, shift.y, choppy) +
                      choppy_wave(q, u_octave_cells[i].y, shift.z, shift.w, choppy);
            h += d * amplitude * kept;
        }
        // What a faded octave leaves: its mean, each term's about 0.62 - 0.066 choppiness (0.36 at 4,
        // 0.47 at 2.2: the mean of (1 - sqrt(s.x s.y))^c over a period, numerically).
        h += 2.0 * (0.62 - 0.066 * choppy) * amplitude * (1.0 - kept);
        uv = OCTAVE_ROTATION * uv + vec2(100.0, 0.0);
        frequency *= 2.0;
        amplitude *= 0.22;
        choppy = mix(choppy, 1.0, 0.2);
    }
    return h;
}

// The highest a crest can reach: each octave's two terms are at most 1 apiece, times its amplitude
// (systems/ocean/ocean_height_map.hpp's ocean_highest_wave on the CPU).
float highest_wave() {
    float sum = 0.0, amplitude = u_ocean_height;
    for (int i = 0; i < MAX_OCTAVES; ++i) {
        if (i >= u_ocean_octaves) break;
        sum += 2.0 * amplitude;
        amplitude *= 0.22;
    }
    return sum;
}
