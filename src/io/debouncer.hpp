#pragma once
// Button and switch debounce: a new level is accepted once it has held, with no further edge, for the
// hold time. Edges carry their kernel timestamps, so bursts of bounce read in one frame still debounce
// by when they happened, not by when the frame read them.

namespace puddle::io {

class Debouncer {
public:
    Debouncer(double hold_seconds, bool level) : hold_(hold_seconds), stable_(level), candidate_(level) {}
    void edge(bool level, double time) {
        candidate_ = level;
        since_ = time;
    }
    // Accepts the candidate level when it has held long enough by `now`; true when the stable level
    // changed in this call.
    bool settle(double now) {
        if (candidate_ == stable_ || now - since_ < hold_) return false;
        stable_ = candidate_;
        return true;
    }
    bool level() const { return stable_; }

private:
    double hold_;
    bool stable_;
    bool candidate_;
    double since_ = 0;
};

}  // namespace puddle::io
