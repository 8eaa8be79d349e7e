// The rain's impacts, hashed per cell of the rain grid and time slot: each cell gets at most one drop per
// slot, with probability u_rain.z, at a hashed place and time, of a Marshall-Palmer size. The wave step
// (its rings) and the surface pass (its splashes) read the same drops. Needs hash.glsl.
uniform vec4 u_rain;        // cells per side, texels per cell, chance of a drop per cell and slot, Marshall-Palmer slope (1/mm)
uniform int u_slot;         // the rain's time slot (RAIN_SLOT seconds each), wrapped to 2^20
uniform float u_slot_time;  // seconds into it

const float RAIN_SLOT = 0.25;  // seconds; a drop's impulse (at most 0.22 s) spans at most two slots

// A Marshall-Palmer diameter from 1 to 4 mm (an exponential of slope u_rain.w, truncated) for u in 0..1.
float drop_diameter(float u) {
    float lambda = u_rain.w;
    return 1.0 - log(1.0 - u * (1.0 - exp(-3.0 * lambda))) / lambda;
}

// The drop of `cell` (of the cells whose drops can reach a texel: rain_cells_near) in the slot k slots
// back, if it fell and hit at most max_age seconds ago: where (texels), how long ago (s), how big (mm).
bool rain_impact(ivec2 cell, int k, float max_age, out vec2 spot, out float age, out float diameter) {
    ivec2 wrapped = (cell + int(u_rain.x)) % int(u_rain.x);
    uint h = hash3(uint(wrapped.x), uint(wrapped.y), uint(u_slot - k) & 0xfffffu);
    if (unit_float(h) >= u_rain.z) return false;
    age = u_slot_time + float(k) * RAIN_SLOT - unit_float(mix_bits(h + 3u)) * RAIN_SLOT;
    if (age < 0.0 || age > max_age) return false;
    spot = (vec2(cell) + vec2(unit_float(mix_bits(h + 1u)), unit_float(mix_bits(h + 2u)))) * u_rain.y;
    diameter = drop_diameter(unit_float(mix_bits(h + 4u)));
    return true;
}

// The first of the 2x2 cells whose drops can reach texel position p (a drop reaches half a cell).
ivec2 rain_cells_near(vec2 p) { return ivec2(floor(p / u_rain.y - 0.5)); }
