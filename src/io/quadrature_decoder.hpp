#pragma once
// Rotary encoder decoding. Lines A and B form a 2-bit Gray code; each valid transition moves one
// quarter-step, a transition that changes both bits at once (a missed edge) counts nothing, and
// contact bounce (A flickering 0-1-0-1) cancels itself out. A detent is reported when the encoder comes
// back to its rest state (the state it idles in) having moved at least half a cycle, so steps lost to
// bounce or skipped states never accumulate into a wrong or doubled detent.

namespace puddle::io {

class QuadratureDecoder {
public:
    // The lines' levels at rest (a detent).
    void reset(bool a, bool b);
    // Feeds the new levels after an edge. Returns +1 (a detent clockwise: A leads B), -1 or 0.
    int update(bool a, bool b);
    int quarter_steps() const { return steps_; }  // progress since the last detent

private:
    static int code(bool a, bool b) { return (a ? 2 : 0) | (b ? 1 : 0); }
    int rest_ = 3;
    int state_ = 3;
    int steps_ = 0;
};

}  // namespace puddle::io
