#pragma once
// A knob at run time: its GPIO lines, its decoder or debouncer, and what it asks for. Opening fails
// softly: one warning naming the chip, the line and the fix, then a retry every few seconds, so a
// late USB GPIO expander or a fixed permission starts working without a restart. A chip unplugged while
// its knobs run is one warning for all of them (GoneChips).

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "io/debouncer.hpp"
#include "io/gpio_backend.hpp"
#include "io/quadrature_decoder.hpp"
#include "params/knob_spec.hpp"

namespace puddle::io {

// What a knob asks for; the live-tuning system turns it into parameter changes.
struct KnobAction {
    enum class Kind { Turn, Press, Level } kind = Kind::Turn;
    const params::KnobSpec* knob = nullptr;
    double amount = 0;   // Turn: signed parameter change (detents x step x acceleration)
    bool level = false;  // Level: the switch's position
};

// The chips whose loss has been warned about: the knobs on one unplugged chip give one warning between
// them, not one each. A chip leaves the list when one of its knobs opens again, so a second unplug warns
// again. Owned by whoever updates the knobs (systems/tuning/live_tuning.cpp); it grows only on an unplug.
class GoneChips {
public:
    // True for the first knob to find `chip` gone, false for the others until it is back.
    bool first_to_find_gone(const std::string& chip);
    void back(const std::string& chip);

private:
    std::vector<std::string> chips_;
};

class Knob {
public:
    static constexpr double retry_seconds = 3.0;

    explicit Knob(params::KnobSpec spec);
    const params::KnobSpec& spec() const { return spec_; }
    bool open() const { return line_a_ != nullptr; }

    // Opens the lines when closed (at most every retry_seconds), reads their edges without blocking,
    // and appends the resulting actions. `out` must have capacity reserved: nothing allocates here but
    // an unplug's entry in `gone`, shared by every knob that is updated together.
    void update(GpioBackend& gpio, double now, std::vector<KnobAction>& out, GoneChips& gone);

private:
    bool try_open(GpioBackend& gpio, double now, std::vector<KnobAction>& out, GoneChips& gone);
    void close_lines();
    void turn(int detent, double time, std::vector<KnobAction>& out);

    params::KnobSpec spec_;
    std::unique_ptr<GpioLine> line_a_, line_b_;
    double next_try_ = 0;
    std::string last_warning_;
    bool unplugged_ =
        false;  // the lines went away and that was warned about; the retry that follows is quiet
    QuadratureDecoder decoder_;
    bool a_ = true, b_ = true;
    double last_detent_ = -1e9;
    Debouncer debouncer_{0.02, false};
    std::vector<LineEvent> events_a_, events_b_;
};

}  // namespace puddle::io
