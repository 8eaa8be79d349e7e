#include "io/quadrature_decoder.hpp"

namespace puddle::io {

namespace {
// [previous][current] quarter-step: clockwise runs 00 -> 10 -> 11 -> 01 -> 00 (A changes first).
// Same state: no move; both bits changed: invalid (an edge was missed), counts nothing.
constexpr int transition[4][4] = {
    // to:  00  01  10  11
    /*00*/ {0, -1, +1, 0},
    /*01*/ {+1, 0, 0, -1},
    /*10*/ {-1, 0, 0, +1},
    /*11*/ {0, +1, -1, 0},
};
}  // namespace

void QuadratureDecoder::reset(bool a, bool b) {
    rest_ = state_ = code(a, b);
    steps_ = 0;
}

int QuadratureDecoder::update(bool a, bool b) {
    const int next = code(a, b);
    steps_ += transition[state_][next];
    state_ = next;
    if (state_ != rest_) return 0;
    // Back at rest: a full cycle is 4 quarter-steps; 2 or more means the turn happened and some
    // edges were lost, less than 2 was bounce that went back.
    const int detent = steps_ >= 2 ? 1 : steps_ <= -2 ? -1 : 0;
    steps_ = 0;
    return detent;
}

}  // namespace puddle::io
