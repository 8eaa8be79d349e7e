#include "render/shader_phase.hpp"

#include <cmath>

namespace puddle::render {

namespace {
// x modulo period in [0, period): floor-based, so negative x wraps upward like a phase should.
double wrap(double x, double period) {
    const double r = x - period * std::floor(x / period);
    return r < period ? r : 0.0;  // x a hair below a multiple of period can round up to period itself
}

// floor(x) modulo 2^32, as a shader's uint.
std::uint32_t whole_mod_2_32(double x) {
    return static_cast<std::uint32_t>(static_cast<std::int64_t>(wrap(std::floor(x), 4294967296.0)));
}
}  // namespace

float periodic_phase(double seconds, double rate, double period) {
    return static_cast<float>(wrap(seconds * rate, period));
}

LatticeShift lattice_shift(double seconds, double rate) {
    const double x = seconds * rate;
    return {.cells = static_cast<std::int32_t>(whole_mod_2_32(x)),
            .fraction = static_cast<float>(x - std::floor(x))};
}

Repetition repetition_at(double seconds, double period, double offset) {
    const double s = seconds / period + offset;
    return {.index = whole_mod_2_32(s), .age = static_cast<float>((s - std::floor(s)) * period)};
}

}  // namespace puddle::render
