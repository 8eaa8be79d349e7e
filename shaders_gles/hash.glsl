// Integer hashes and value noise. Integer arithmetic gives the same bits on every GPU, where sine-based
// float hashes differ between drivers; tests and synchronised screens need the same picture everywhere.

uint mix_bits(uint x) {
    x ^= x >> 15u;
    x *= 0x2c1b3c6du;
    x ^= x >> 12u;
    x *= 0x297a2d39u;
    x ^= x >> 15u;
    return x;
}

uint hash3(uint a, uint b, uint c) { return mix_bits(a ^ mix_bits(b ^ mix_bits(c + 0x9e3779b9u))); }

// 0..1 from the top 24 bits (exact in a float).
float unit_float(uint h) { return float(h >> 8u) / 16777216.0; }

float hash_cell(ivec2 c, uint salt) { return unit_float(hash3(uint(c.x), uint(c.y), salt)); }

// Value noise in 0..1: hashed lattice values, smoothly interpolated.
float value_noise(vec2 p, uint salt) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    ivec2 c = ivec2(i);
    float a = hash_cell(c, salt);
    float b = hash_cell(c + ivec2(1, 0), salt);
    float d = hash_cell(c + ivec2(0, 1), salt);
    float e = hash_cell(c + ivec2(1, 1), salt);
    return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}

// value_noise(p + vec2(cells)) for a pattern scrolled by `cells` whole lattice cells plus the small p.
// A scroll that grows with time is split that way on the CPU (src/render/shader_phase.hpp): the whole
// cells are added to the lattice exactly, as the bits of the uint the hash takes (wrapping at 2^32 cells
// like the CPU's count), so p keeps its precision however far the pattern has moved.
float scrolled_value_noise(vec2 p, ivec2 cells, uint salt) {
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    uvec2 c = uvec2(ivec2(floor(p))) + uvec2(cells);
    float a = unit_float(hash3(c.x, c.y, salt));
    float b = unit_float(hash3(c.x + 1u, c.y, salt));
    float d = unit_float(hash3(c.x, c.y + 1u, salt));
    float e = unit_float(hash3(c.x + 1u, c.y + 1u, salt));
    return mix(mix(a, b, u.x), mix(d, e, u.x), u.y);
}
