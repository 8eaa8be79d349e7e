#pragma once
// What other features ask of live tuning: a remote value or preset, a config reload (SIGHUP, a remote
// command), a state save, the schedule's entries in force. Sources push requests into the TuningInbox
// resource; only live tuning drains it, first thing in its step, and acts on them in order, so every change
// has one path and the flags that track a change (pending, why, when a wall applies it, unsaved) are live
// tuning's own.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "params/param_store.hpp"

namespace puddle::systems {

// A value set from the remote layer. apply_at_ns: with wall.clock = "realtime", when the wall applies it
// (ns since the Unix epoch), as the message asked (systems/tuning/synced_changes.hpp).
struct SetRemoteValue {
    params::ParamId id;
    params::ParamValue value;
    std::optional<std::int64_t> apply_at_ns;
};
// A preset chosen from the remote layer; an empty name goes back to the config's. The sender checks that
// the preset loads (so it can answer on its own channel); a preset that fails later is logged and ignored.
struct SelectPreset {
    std::string name;
    const char* source = "remote";  // for the log line
    std::optional<std::int64_t> apply_at_ns;
};
// Read the config file and presets again, now.
struct ReloadConfig {
    const char* source = "SIGHUP";
};
// Write the knob and remote state now (the "save" button or command), on the saver thread.
struct SaveState {};
// The schedule's entries in force at a transition, a reload or a clock step (systems/tuning/
// schedule_system.hpp): the entries now active (indices into the config's [[schedule]]), those whose knob
// and remote values a transition forgets, and the reason for the log line ("schedule: schedule[2] (...)
// starts"). Asked only when something changes, so its vectors and string are allocated at a transition.
struct SetSchedule {
    std::vector<int> active;
    std::vector<int> forget_knobs_of;
    std::string reason;
};

using TuningRequest = std::variant<SetRemoteValue, SelectPreset, ReloadConfig, SaveState, SetSchedule>;

// Resource: the queue. Bounded: a source that floods it (the remote's own inbox is bounded too) loses the
// newest requests, counted in `dropped` and logged by live tuning.
struct TuningInbox {
    static constexpr std::size_t capacity = 256;

    TuningInbox() { requests.reserve(capacity); }
    // One of TuningRequest's alternatives, built in place (moving a whole variant makes GCC 12 at -O3 warn
    // -Wmaybe-uninitialized about the alternatives not held).
    template <class Request>
    void push(Request request) {
        if (requests.size() < capacity)
            requests.emplace_back(std::in_place_type<Request>, std::move(request));
        else
            ++dropped;
    }

    std::vector<TuningRequest> requests;
    std::uint64_t dropped = 0;
};

}  // namespace puddle::systems
