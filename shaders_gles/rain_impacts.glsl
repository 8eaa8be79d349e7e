// The rain's impacts, hashed per cell of the rain grid and time slot: each cell gets at most one drop per
// slot, with probability u_rain.z, at a hashed place and time, of a Marshall-Palmer size. rain_cells.frag
// hashes them once a pass into the rain cells' table, which the wave step (the rings) and the surface
// pass (the splashes) read (rain_cells.glsl). Needs hash.glsl.
uniform vec4 u_rain;        // cells per side, texels per cell, chance of a drop per cell and slot, Marshall-Palmer slope (1/mm)
// The rain's time slot (RAIN_SLOT seconds each) and the one before it, each hashed with rain.seed on the
// CPU (rain_slot_key, systems/water/wave_system.hpp), so a cell takes one round of mixing, not three.
uniform ivec2 u_slot_keys;
uniform float u_slot_time;  // seconds into the slot

const float RAIN_SLOT = 0.25;  // seconds; a drop's impulse (at most 0.22 s) spans at most two slots
const float SPLASH_SECONDS = 0.06;  // how long a splash lasts (surface.frag draws it)

// A Marshall-Palmer diameter from 1 to 4 mm (an exponential of slope u_rain.w, truncated) for u in 0..1.
float drop_diameter(float u) {
    float lambda = u_rain.w;
    return 1.0 - log(1.0 - u * (1.0 - exp(-3.0 * lambda))) / lambda;
}

// The drop of `cell` (0 to u_rain.x - 1 each way) in the slot k slots back, if it fell and hit at most
// max_age seconds ago: where in the cell (0..1 each way), how long ago (s), how big (mm).
bool rain_impact(ivec2 cell, int k, float max_age, out vec2 within, out float age, out float diameter) {
    uint h = mix_bits(uint(u_slot_keys[k]) ^ uint(cell.x + cell.y * int(u_rain.x)));
    if (unit_float(h) >= u_rain.z) return false;
    age = u_slot_time + float(k) * RAIN_SLOT - unit_float(mix_bits(h + 3u)) * RAIN_SLOT;
    if (age < 0.0 || age > max_age) return false;
    within = vec2(unit_float(mix_bits(h + 1u)), unit_float(mix_bits(h + 2u)));
    diameter = drop_diameter(unit_float(mix_bits(h + 4u)));
    return true;
}
