#version 300 es
// Rain on a window at night (scene.kind = window), drawn in screen space. The eye is focused on the glass,
// so the city behind it is out of focus: each light is a bokeh disc, the circle of confusion of a point
// source. On the glass, still beads of rain and drops that run down in stick-slip jumps, wiping a trail
// that new beads refill. A bead is a small lens: it shows the city upside down and in focus, lights as
// points, with a dark rim where its steep edge reflects the dark room (total internal reflection).
// docs/techniques.md ("Rain on a window") gives the figures.
precision highp float;
precision highp int;

#include "hash.glsl"
#include "colour.glsl"

in vec2 v_uv;  // 0..1 across the whole view, of which this target may be a tile (view_window.vert)
out vec4 o_color;

uniform float u_aspect;  // width / height of the whole view (a whole video wall)

uniform float u_window_view_height;  // metres of glass from the bottom of the view to its top
uniform float u_window_beads;        // 0..1: how much of the glass the still beads may cover
uniform int u_window_streams;        // drops running down at once (one column each)
uniform float u_window_slide_speed;  // metres a second, on average
uniform float u_window_blur;         // 0..1: how far out of focus the city is
uniform float u_window_lights;       // 0..1: how many of the city's lights are on
uniform float u_window_traffic;      // 0..1: how many cars pass in the street below
uniform float u_window_exposure;     // stops
uniform int u_rain_seed;             // rain.seed: where the beads sit (the runs' seed comes with their repeats)

const int MAX_STREAMS = 32;
const float BEAD_CELL = 0.005;   // metres: the still beads' grid; a bead's radius is at most half of it
const float MIST_CELL = 0.0016;  // the fine beads' grid
const float STREAM_REACH = 0.0064;  // metres: a running drop's largest radius and its wander, sideways
const float TRAIL_REFILL = 6.0;  // seconds until a wiped trail holds beads again (window_trail_refill)

// Time arrives as phases computed on the CPU in double (systems/window/window_system.hpp), each within the
// period it repeats at, so the window is continuous however long the display runs.
uniform float u_bead_phase;              // fraction of a bead's life, window.bead_life seconds
uniform int u_bead_cycle;                // whole lives since the start (the bits of a uint)
uniform float u_traffic_shift;           // the cars' drift: fraction of a lattice cell
uniform int u_traffic_cells;             // and whole cells
uniform float u_wetness;                 // 0..1, from the rain rate now (rain.rate, rain.drift)
uniform float u_stream_age[MAX_STREAMS];  // seconds since stream i's drop set off in its current repeat
uniform int u_stream_repeat[MAX_STREAMS];  // which repeat (the bits of a uint): where the drop runs

// --- hashing ---------------------------------------------------------------------------------------------
// The many cells here are hashed with one mix_bits each (hash.glsl's hash3 takes three), and a hash's bytes
// give a cell's several random values: a quarter of the work where every pixel looks at dozens of cells.
uint cell_hash(ivec2 c, uint salt) { return mix_bits(uint(c.x) * 0x8da6b343u ^ uint(c.y) * 0xd8163841u ^ salt); }
// Byte k (0..3) of h as 0..1.
float byte_of(uint h, int k) { return float((h >> uint(8 * k)) & 255u) / 255.0; }

// --- the city behind the glass -------------------------------------------------------------------------

// Light colours of a city at night: sodium and warm tungsten most, then cool LED, neon red, green, blue.
vec3 light_color(float h) {
    if (h < 0.35) return vec3(1.0, 0.55, 0.2);
    if (h < 0.62) return vec3(1.0, 0.8, 0.55);
    if (h < 0.8) return vec3(0.75, 0.85, 1.0);
    if (h < 0.88) return vec3(1.0, 0.18, 0.12);
    if (h < 0.94) return vec3(0.25, 1.0, 0.55);
    return vec3(0.35, 0.5, 1.0);
}

// One light of radius r (its disc's radius when out of focus) at distance d: a flat disc with a slightly
// brighter rim, as a lens' bokeh has; in focus (sharp = 1) a small bright point. Same energy either way.
float bokeh(float d, float r, float sharp) {
    float radius = mix(r, 0.06 * r, sharp);
    float edge = max(radius * 0.12, 0.0006);
    float disc = smoothstep(radius + edge, radius - edge, d);
    float rim = 0.8 + 0.35 * smoothstep(radius * 0.5, radius, d);
    return disc * mix(rim, 1.0, sharp) * (r * r) / (radius * radius);
}

// The buildings across the street: blocks BLOCK view heights wide with gaps between some, each its own
// roof height, most above the middle of the view and some beyond its top.
const float BLOCK = 0.21;
// Block b's roof height (z, view heights) and side walls (x, y: fractions of the block; some stand apart,
// some touch their neighbours), from one hash.
vec3 block_shape(int b) {
    uint h = cell_hash(ivec2(b, 0), 97u);
    return vec3(0.12 * byte_of(h, 0), 1.0 - 0.12 * byte_of(h, 1), 0.55 + 0.55 * unit_float(h));
}
// 1 inside the buildings' mass at q, 0 in the sky: each block a rectangle blurred by `soft` (view
// heights), as far out of focus as the city is.
float buildings(vec2 q, float soft) {
    float x = q.x / BLOCK;
    int b = int(floor(x));
    float mass = 0.0;
    for (int k = -1; k <= 1; ++k) {
        vec3 shape = block_shape(b + k);
        vec2 w = (vec2(float(b + k)) + shape.xy) * BLOCK;
        float across = smoothstep(w.x - soft, w.x + soft, q.x) * (1.0 - smoothstep(w.y - soft, w.y + soft, q.x));
        float up = 1.0 - smoothstep(shape.z - soft, shape.z + soft, q.y);
        mass = max(mass, across * up);
    }
    return mass;
}

// The lights of one layer of grid cells `cell` (view heights) wide around q (x from the view's centre in
// view heights, y 0..1 from the bottom), with at most one light a cell.
vec3 light_layer(vec2 q, float cell, float density, uint salt, float sharp) {
    vec3 sum = vec3(0.0);
    // A light reaches at most 0.25 + 0.53 of a cell from its cell's centre, under the 1 cell beyond which
    // only the 2x2 cells nearest q can reach it.
    vec2 p = q / cell;
    ivec2 base = ivec2(floor(p - 0.5));
    float r = cell * mix(0.18, 0.48, u_window_blur);
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            ivec2 c = base + ivec2(i, j);
            uint h = cell_hash(c, salt), g = mix_bits(h);
            vec2 centre = (vec2(c) + 0.5 + (vec2(byte_of(g, 0), byte_of(g, 1)) - 0.5) * 0.5) * cell;
            // Lit windows within the buildings, street lights low down; the sky above the roofs has few.
            int block = int(floor(centre.x / BLOCK));
            vec3 shape = block_shape(block);
            vec2 w = (vec2(float(block)) + shape.xy) * BLOCK;
            bool in_building = centre.y < shape.z && centre.x > w.x && centre.x < w.y;
            float here = density * (in_building ? 1.0 : 0.06) * smoothstep(0.02, 0.15, centre.y);
            if (unit_float(h) >= here) continue;
            // Many dim lights, a few bright ones; nearer ones make larger discs.
            float b = byte_of(g, 2);
            float brightness = 0.12 + 1.2 * b * b;
            float size = mix(0.6, 1.1, byte_of(g, 3));
            sum += light_color(byte_of(h, 0)) * brightness * bokeh(distance(q, centre), r * size, sharp);
        }
    }
    return sum;
}

// The far lights: smaller discs, each kept within its own cell (radius, soft edge and offset under half a
// cell), so one cell is all a pixel looks at: a quarter of light_layer's work for the many small lights.
vec3 far_lights(vec2 q, float cell, float density, uint salt, float sharp) {
    ivec2 c = ivec2(floor(q / cell));
    uint h = cell_hash(c, salt), g = mix_bits(h);
    // At most 0.2 off the centre, a radius of at most 0.22 x 1.1 and its edge of 0.12 of it: 0.47 of a cell.
    vec2 centre = (vec2(c) + 0.5 + (vec2(byte_of(g, 0), byte_of(g, 1)) - 0.5) * 0.4) * cell;
    float here = density * smoothstep(0.02, 0.15, centre.y) * smoothstep(0.75, 0.5, centre.y);
    if (unit_float(h) >= here) return vec3(0.0);
    float b = byte_of(g, 2);
    float r = cell * mix(0.1, 0.22, u_window_blur) * mix(0.7, 1.1, byte_of(g, 3));
    return light_color(byte_of(h, 0)) * (0.12 + 1.2 * b * b) * bokeh(distance(q, centre), r, sharp);
}

// Cars in the street below: tail lights drifting right in the far lane, headlights left in the near one.
vec3 traffic(vec2 q, float sharp) {
    vec3 sum = vec3(0.0);
    float cell = 0.11;
    float r = cell * mix(0.2, 0.42, u_window_blur);
    for (int lane = 0; lane < 2; ++lane) {
        float y = lane == 0 ? 0.2 : 0.1;
        float dir = lane == 0 ? 1.0 : -1.0;
        // The lane's lattice moves by (cells + shift) cells: whole cells in the hash, the fraction in x.
        float x = q.x / cell - dir * u_traffic_shift;
        int base = int(floor(x - 0.5));  // a car reaches under a cell from its cell's centre
        for (int i = 0; i <= 1; ++i) {
            int c = base + i;
            uint h = cell_hash(ivec2(int(uint(c) - uint(int(dir) * u_traffic_cells)), lane), 71u);
            if (unit_float(h) >= u_window_traffic) continue;
            // Each car a little higher or lower (its lights, its distance) and its own size.
            vec2 centre = vec2(float(c) + 0.5 + (byte_of(h, 0) - 0.5) * 0.4, (y + (byte_of(h, 2) - 0.5) * 0.03) / cell);
            vec3 col = lane == 0 ? vec3(1.0, 0.1, 0.06) : vec3(1.0, 0.92, 0.8);
            float d = distance(vec2(x, q.y / cell), centre) * cell;
            sum += col * (lane == 0 ? 0.8 : 1.4) * bokeh(d, r * mix(0.75, 1.05, byte_of(h, 1)), sharp);
        }
    }
    return sum;
}

// The view through clear glass at q: the night (a glow of city light above the roofs, dark street), the
// city's lights and the cars. sharp = 1 is the view in focus, as a bead's lens shows it.
vec3 city(vec2 q, float sharp) {
    // The night sky glows with the city's light above the roofs; the buildings are darker masses, lit a
    // little from the street below.
    vec3 sky = mix(vec3(0.11, 0.06, 0.035), vec3(0.012, 0.016, 0.03), smoothstep(0.55, 1.05, q.y));
    sky = mix(vec3(0.03, 0.024, 0.024), sky, smoothstep(0.2, 0.65, q.y));  // low down, streets beyond
    vec3 facade = mix(vec3(0.035, 0.028, 0.026), vec3(0.014, 0.013, 0.016), smoothstep(0.0, 0.6, q.y));
    vec3 col = mix(sky, facade, buildings(q, mix(0.012, 0.07, u_window_blur * (1.0 - sharp))));
    col += light_layer(q, 0.085, 0.42 * u_window_lights, 31u, sharp);
    col += far_lights(q + vec2(0.3, 0.0), 0.06, 0.5 * u_window_lights, 37u, sharp) * 0.6;
    col += traffic(q, sharp);
    return col;
}

// --- the glass -----------------------------------------------------------------------------------------

// A drop on the glass that covers the point: its offset from the centre in radii (|o| < 1) and its centre
// in view units; cover 0 where none is.
struct Lens {
    vec2 o;
    vec2 centre;
    float cover;
};

// Where the drop of stream i is `s` metres down its run: its sideways wander (metres), a few millimetres,
// the same for the drop and the trail it leaves.
float wander(float s, uint h) {
    float a = unit_float(h) * 6.2832, b = unit_float(mix_bits(h)) * 6.2832;
    return 0.0018 * sin(s * 41.0 + a) + 0.0011 * sin(s * 97.0 + b);
}

// Distance run after `age` seconds: average speed v with a stick-slip surge of f Hz (always forwards).
float run_distance(float age, float v, float f) {
    float w = 6.2832 * f;
    return v * (age - 0.7 * sin(w * age) / w);
}

// Whether a bead centred at c (metres) is still wiped away: its centre lies in the trail (whose middle at
// nearby heights is trail_x, the wander changing little over a bead) and the drop passed it less than
// `refill` seconds ago. Tested at the centre, so a bead is there whole or not at all.
bool trail_wiped(vec2 c, float refill, float trail_x, float trail_half, float run_top, float run_s, float run_age) {
    float along = run_top - c.y;
    if (along <= 0.0 || along >= run_s || abs(c.x - trail_x) >= trail_half) return false;
    return run_age * (1.0 - along / run_s) < refill;
}

void main() {
    vec2 uv = v_uv;
    vec2 q = vec2((uv.x - 0.5) * u_aspect, uv.y);                         // view heights
    vec2 g = vec2((uv.x - 0.5) * u_aspect, uv.y - 0.5) * u_window_view_height;  // metres on the glass
    float half_width = 0.5 * u_aspect * u_window_view_height;
    float top = 0.5 * u_window_view_height;

    // The runs: stream i's column, its drop and the trail above it.
    Lens lens = Lens(vec2(0.0), vec2(0.0), 0.0);
    float trail_edge = 0.0;
    // The pixel's column's trail, for the beads to ask whether their centre lies in it (trail_wiped): its
    // middle at this height, half-width, the top of the run, the distance run and the age of the run.
    float trail_x = 0.0, trail_half = 0.0, run_top = 0.0, run_s = 0.0, run_age = 0.0;
    int streams = min(u_window_streams, MAX_STREAMS);
    if (streams > 0) {
        // A drop and its trail stay inside their column: in a column narrower than twice their reach
        // (STREAM_REACH: the largest radius and the wander), they run smaller. So one column is all a pixel
        // looks at.
        float column = 2.0 * half_width / float(streams);
        float fit = min(1.0, 0.5 * column / STREAM_REACH), reach = STREAM_REACH * fit;
        int i = clamp(int(floor((g.x + half_width) / column)), 0, streams - 1);
        {
            uint h = hash3(uint(i), uint(u_stream_repeat[i]), 401u);
            float age = u_stream_age[i];
            float v = u_window_slide_speed * mix(0.6, 1.5, unit_float(mix_bits(h)));
            float radius = mix(0.0019, 0.0034, unit_float(mix_bits(h + 1u))) * fit;
            float x0 = -half_width + column * float(i) + mix(reach, column - reach, unit_float(mix_bits(h + 2u)));
            float s = run_distance(age, v, mix(0.5, 1.1, unit_float(mix_bits(h + 3u))));
            vec2 drop = vec2(x0 + wander(s, h) * fit, top + radius - s);
            // The drop: a little longer than wide, fuller at the bottom.
            vec2 d = g - drop;
            vec2 o = vec2(d.x, d.y * (d.y < 0.0 ? 0.8 : 0.62)) / radius;
            if (dot(o, o) < 1.0 && lens.cover < 1.0) lens = Lens(o, drop, 1.0);
            // The trail: the path above the drop, a little narrower than it.
            float along = top + radius - g.y;  // metres of run to this height
            trail_x = x0 + wander(max(along, 0.0), h) * fit;
            trail_half = 0.55 * radius;
            run_top = top + radius;
            run_s = s;
            run_age = age;
            if (along > 0.0 && along < s) {
                float across = abs(g.x - trail_x);
                if (across < trail_half) {
                    float passed = age * (1.0 - along / s);
                    // Its wet edges dry as beads refill it.
                    trail_edge = smoothstep(0.6 * trail_half, trail_half, across) *
                                 (1.0 - smoothstep(0.3, 1.0, passed / TRAIL_REFILL));
                }
                // Now and then the trail leaves a tiny bead behind, which the refill takes in again.
                float step_m = 0.0045;
                float n = floor(along / step_m);
                uint hb = hash3(uint(int(n)), h, 409u);
                float left = age * (1.0 - (n + 0.5) * step_m / s);  // seconds since it was left
                if (unit_float(hb) < 0.5 && left > 0.0 && left < TRAIL_REFILL) {
                    vec2 c = vec2(x0 + wander((n + 0.5) * step_m, h) * fit, top + radius - (n + 0.5) * step_m);
                    float rb = mix(0.0004, 0.0009, unit_float(mix_bits(hb))) *
                               (1.0 - smoothstep(0.5, 1.0, left / TRAIL_REFILL));
                    vec2 ob = (g - c) / rb;
                    if (dot(ob, ob) < 1.0 && lens.cover < 1.0) lens = Lens(ob, c, 1.0);
                }
            }
        }
    }

    // The still beads, renewed each bead life: a new place and size per cell and life, the cells' lives
    // staggered. A bead in a trail a drop wiped less than TRAIL_REFILL seconds ago is not there yet.
    float coverage = u_window_beads * u_wetness;
    uint seed = uint(u_rain_seed) * 0x9e3779b9u;  // rain.seed chooses where the beads sit
    if (lens.cover < 1.0) {
        // A bead reaches at most 0.45 + 0.46 of a cell from its cell's centre: the 2x2 nearest cells.
        vec2 p = g / BEAD_CELL;
        ivec2 base = ivec2(floor(p - 0.5));
        for (int j = 0; j <= 1; ++j) {
            for (int i = 0; i <= 1; ++i) {
                ivec2 c = base + ivec2(i, j);
                float phase = u_bead_phase + unit_float(cell_hash(c, 503u ^ seed));
                uint life = uint(u_bead_cycle) + (phase >= 1.0 ? 1u : 0u);
                float a = fract(phase);
                uint h = cell_hash(c, (life * 2654435761u + 17u) ^ seed), k = mix_bits(h);
                if (unit_float(h) >= coverage) continue;
                float size = byte_of(k, 0);
                float radius = BEAD_CELL * mix(0.12, 0.46, size * size);  // many small, a few large
                radius *= smoothstep(0.0, 0.015, a) * (1.0 - smoothstep(0.93, 1.0, a));
                vec2 centre = (vec2(c) + 0.5 + (vec2(byte_of(k, 1), byte_of(k, 2)) - 0.5) * 0.9) * BEAD_CELL;
                vec2 o = (g - centre) / max(radius, 1e-6);
                if (dot(o, o) >= 1.0) continue;
                if (trail_wiped(centre, TRAIL_REFILL * byte_of(k, 3), trail_x, trail_half, run_top, run_s, run_age))
                    continue;
                lens = Lens(o, centre, 1.0);
            }
        }
    }
    // The fine beads between them: one cell each, smaller than its cell, so no neighbour reaches here.
    float mist = 0.0;
    if (lens.cover < 1.0) {
        // Their lives staggered like the beads', so they renew a few at a time, never all at once.
        vec2 p = g / MIST_CELL;
        ivec2 c = ivec2(floor(p));
        float phase = u_bead_phase + unit_float(cell_hash(c, 607u ^ seed));
        uint life = uint(u_bead_cycle) + (phase >= 1.0 ? 1u : 0u);
        float a = fract(phase);
        uint h = cell_hash(c, (life * 7u + 601u) ^ seed), k = mix_bits(h);
        if (unit_float(h) < coverage * 0.5) {
            // Anywhere in its cell that it fits, so the fine beads show no grid.
            float radius = mix(0.08, 0.2, byte_of(k, 0));  // cells
            vec2 u = vec2(byte_of(k, 1), byte_of(k, 2));
            vec2 centre = (vec2(c) + radius + u * (1.0 - 2.0 * radius)) * MIST_CELL;
            radius *= smoothstep(0.0, 0.015, a) * (1.0 - smoothstep(0.93, 1.0, a));
            vec2 o = (g - centre) / max(radius * MIST_CELL, 1e-6);
            if (!trail_wiped(centre, TRAIL_REFILL * byte_of(k, 3), trail_x, trail_half, run_top, run_s, run_age))
                mist = max(0.0, 1.0 - dot(o, o));
        }
    }

    // One look at the city per pixel: through the drop where one covers it, else through clear glass.
    vec2 centre = vec2(lens.centre.x, lens.centre.y + 0.5 * u_window_view_height) / u_window_view_height;
    float r2 = dot(lens.o, lens.o);
    bool in_drop = lens.cover > 0.0;
    // A drop is a wide-angle lens of a few millimetres' focal length: it shows the city upside down and
    // shrunk, about a third of the view across its disc, nearer focus than the glass around it (smaller
    // discs).
    vec3 color = city(in_drop ? centre - lens.o * 0.16 * vec2(1.0, 1.2) : q, in_drop ? 0.55 : 0.0);
    if (in_drop) {
        // A little brighter, as it gathers light from that wider field. Toward the rim the surface is
        // steep: it reflects the dark room (total internal reflection), with a crescent of the city's
        // glow focused at the bottom edge and the room's light, faint, off its upper side.
        color *= 1.3 * mix(1.0, 0.25, smoothstep(0.78, 1.0, r2));
        float crescent = smoothstep(0.55, 0.9, r2) * smoothstep(0.3, 0.9, -lens.o.y) * (1.0 - smoothstep(0.93, 1.0, r2));
        color += vec3(0.22, 0.13, 0.08) * crescent;
        vec2 glint = lens.o - vec2(-0.3, 0.45);
        color += vec3(0.05, 0.047, 0.045) * exp(-14.0 * dot(glint, glint));
    } else {
        // A fine bead: a speck of focused light with a dark rim. A wiped trail is clearer glass with wet edges.
        color *= 1.0 + 0.5 * smoothstep(0.5, 1.0, mist) - 0.45 * smoothstep(0.0, 0.5, mist) * (1.0 - smoothstep(0.5, 1.0, mist));
        color *= 1.0 - 0.1 * trail_edge;
    }
    color *= exp2(u_window_exposure);
    // A soft shoulder, as a camera's curve: lights stay coloured instead of clipping to white.
    color = color / (1.0 + color * 0.6);
    color *= 1.0 - 0.35 * dot(uv - 0.5, uv - 0.5);
    o_color = vec4(encode_srgb(color), 1.0);
}
