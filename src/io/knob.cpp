#include "io/knob.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <utility>

namespace puddle::io {

namespace {
constexpr std::size_t max_events = 64;  // per line per frame; the kernel keeps 16 by default anyway
}  // namespace

bool GoneChips::first_to_find_gone(const std::string& chip) {
    if (std::find(chips_.begin(), chips_.end(), chip) != chips_.end()) return false;
    chips_.push_back(chip);
    return true;
}

void GoneChips::back(const std::string& chip) {
    std::erase(chips_, chip);
}

Knob::Knob(params::KnobSpec spec) : spec_(std::move(spec)), debouncer_(spec_.debounce_ms * 1e-3, false) {
    events_a_.resize(max_events);
    events_b_.resize(max_events);
}

void Knob::close_lines() {
    line_a_.reset();
    line_b_.reset();
}

bool Knob::try_open(GpioBackend& gpio, double now, std::vector<KnobAction>& out, GoneChips& gone) {
    if (now < next_try_) return false;
    next_try_ = now + retry_seconds;
    LineRequest request{spec_.chip, spec_.line, spec_.active_low, spec_.bias};
    auto a = gpio.request(request);
    Result<std::unique_ptr<GpioLine>> b = std::unique_ptr<GpioLine>();
    if (a && spec_.kind == params::KnobKind::Encoder) {
        request.line = spec_.line_b;
        b = gpio.request(request);
    }
    if (!a || !b) {
        const std::string message = (!a ? a.error() : b.error()).message;
        // One warning per distinct problem: a knob that stays unplugged does not flood the journal. Just
        // after its lines went away the chip is missing: the same unplug, already warned about.
        const bool unplug_warned = std::exchange(unplugged_, false);
        if (message != last_warning_ && !unplug_warned)
            spdlog::warn("{} (knob: {}; retrying every {:g} s)", message, spec_.describe(), retry_seconds);
        last_warning_ = message;
        return false;
    }
    unplugged_ = false;
    gone.back(spec_.chip);
    line_a_ = std::move(*a);
    line_b_ = std::move(*b);
    if (!last_warning_.empty()) spdlog::info("gpio: knob {} works now", spec_.describe());
    last_warning_.clear();
    auto level_a = line_a_->level();
    auto level_b = line_b_ ? line_b_->level() : Result<bool>(false);
    if (!level_a || !level_b) {
        close_lines();
        return false;
    }
    a_ = *level_a;
    b_ = *level_b;
    switch (spec_.kind) {
        case params::KnobKind::Encoder:
            decoder_.reset(a_, b_);
            break;
        case params::KnobKind::Button:
            debouncer_ = Debouncer(spec_.debounce_ms * 1e-3, a_);
            break;
        case params::KnobKind::Switch:
            debouncer_ = Debouncer(spec_.debounce_ms * 1e-3, a_);
            out.push_back({KnobAction::Kind::Level, &spec_, 0, a_});  // the switch's position applies at once
            break;
    }
    return true;
}

void Knob::turn(int detent, double time, std::vector<KnobAction>& out) {
    // Acceleration: a fast turn moves further per detent. At r detents/s the step grows by
    // acceleration x (r - 2) / 6, so acceleration 1 doubles it at 8 detents/s; capped at 20x.
    const double rate = 1.0 / std::max(time - last_detent_, 1e-3);
    last_detent_ = time;
    const double gain = std::min(20.0, 1.0 + spec_.acceleration * std::max(0.0, rate - 2.0) / 6.0);
    out.push_back({KnobAction::Kind::Turn, &spec_, detent * spec_.step * gain, false});
}

void Knob::update(GpioBackend& gpio, double now, std::vector<KnobAction>& out, GoneChips& gone) {
    if (!line_a_ && !try_open(gpio, now, out, gone)) return;
    auto na = line_a_->read_events(events_a_);
    auto nb = line_b_ ? line_b_->read_events(events_b_) : Result<std::size_t>(std::size_t{0});
    if (!na || !nb) {
        const std::string& message = (!na ? na.error() : nb.error()).message;
        if (gone.first_to_find_gone(spec_.chip))
            spdlog::warn("{} (knob: {}); chip {} and every knob on it: retrying every {:g} s", message,
                         spec_.describe(), spec_.chip, retry_seconds);
        else
            spdlog::debug("{} (knob: {}); its chip's loss was already warned about", message,
                          spec_.describe());
        last_warning_ = "gone";
        unplugged_ = true;
        close_lines();
        next_try_ = now + retry_seconds;
        return;
    }
    if (spec_.kind == params::KnobKind::Encoder) {
        // Merge both lines' edges in time order; each edge changes one line.
        std::size_t i = 0, j = 0;
        while (i < *na || j < *nb) {
            const bool take_a = j >= *nb || (i < *na && events_a_[i].time <= events_b_[j].time);
            const LineEvent& e = take_a ? events_a_[i++] : events_b_[j++];
            (take_a ? a_ : b_) = e.level;
            if (const int detent = decoder_.update(a_, b_)) turn(detent, e.time, out);
        }
        return;
    }
    auto accepted = [&] {
        if (spec_.kind == params::KnobKind::Button && debouncer_.level())
            out.push_back({KnobAction::Kind::Press, &spec_, 0, true});
        if (spec_.kind == params::KnobKind::Switch)
            out.push_back({KnobAction::Kind::Level, &spec_, 0, debouncer_.level()});
    };
    for (std::size_t i = 0; i < *na; ++i) {
        // A level that had held long enough before this edge counts, even if both came in one frame.
        if (debouncer_.settle(events_a_[i].time)) accepted();
        debouncer_.edge(events_a_[i].level, events_a_[i].time);
    }
    if (debouncer_.settle(now)) accepted();
}

}  // namespace puddle::io
