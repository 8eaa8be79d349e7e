#pragma once
// Time for shaders, for a display that runs for years: a shader never sees simulated time itself (a float
// second has steps of 8 s at 10^8 s of uptime, and wrapping it makes every term jump at the wrap). Each
// periodic term of a look instead gets its own phase, rate * seconds reduced modulo that term's exact
// period here in double precision (10^8 s * 100 / s is still exact to about 10^-6), so a term is
// continuous for as long as the clock runs and its float stays small. A pattern that moves without
// repeating (value noise scrolled by time) gets its scroll split into whole lattice cells, which the
// shader adds to the integer lattice exactly (scrolled_value_noise in shaders_gles/hash.glsl), and the
// fraction of a cell, which stays small.

#include <cstdint>

namespace puddle::render {

// rate * seconds modulo period, in [0, period): the float a shader adds where it used rate * time.
// Rates may be negative (a term travelling the other way); period > 0.
float periodic_phase(double seconds, double rate, double period);

// rate * seconds lattice cells, split: the whole cells modulo 2^32 (the bits of the uint a shader's hash
// takes, so its integer sums wrap exactly where this count does) and the fraction in [0, 1).
struct LatticeShift {
    std::int32_t cells = 0;
    float fraction = 0;
};
LatticeShift lattice_shift(double seconds, double rate);

// One repetition of a term that restarts every `period` seconds, offset by `offset` periods: which
// repetition it is (modulo 2^32, the width of a shader's uint hash input) and the seconds since it began.
struct Repetition {
    std::uint32_t index = 0;
    float age = 0;  // seconds, in [0, period)
};
Repetition repetition_at(double seconds, double period, double offset);

}  // namespace puddle::render
