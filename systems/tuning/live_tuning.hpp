#pragma once
// Live tuning: the input-stage system that keeps Params up to date while the display runs. It reloads
// the config when the file changes (inotify) or on SIGHUP, turns knob events into parameter changes,
// saves the knob state a few seconds after the last turn (on a worker thread: an SD card can take
// seconds to fsync, and frames must not wait for it), and recomposes the effective Params from the
// layers (defaults < preset < config < schedule < knobs < --set) whenever one of them changed. Other systems
// just read Params; a value that needs a rebuild (wave resolution) is rebuilt by the system that owns it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "io/gpio_backend.hpp"
#include "io/knob.hpp"
#include "params/config_watcher.hpp"
#include "params/param_layers.hpp"
#include "params/state_store.hpp"
#include "systems/tuning/tuning_request.hpp"
#include "util/background_job.hpp"
#include "util/monotonic_clock.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource. The set-up (layers, config path, preset folders, GPIO, state store) is filled in before
// add_live_tuning; what tracks a change in flight is private to live tuning (live_tuning.cpp), and other
// features ask for changes through the TuningInbox (systems/tuning/tuning_request.hpp).
class LiveTuning {
public:
    static constexpr double save_delay_seconds = 3.0;

    explicit LiveTuning(params::ParamLayers l) : layers(std::move(l)) {}
    params::ParamLayers layers;
    std::string config_path;                  // empty: no config file, nothing to watch
    std::vector<std::string> preset_folders;  // read again with every reload (Presets::load)
    std::unique_ptr<io::GpioBackend> gpio;
    std::optional<params::StateStore> state;

    // Counts the reloads that applied (the schedule and the zone check follow it).
    std::uint64_t config_generation() const { return in_.config_generation; }
    // The knob and remote state has changes not yet on disk (saved a delay after the last change).
    bool state_unsaved() const { return in_.state_dirty; }
    // Start-up: the restored state was repaired, so it is written on the first frame.
    void save_soon() { in_.state_dirty = true; }
    // Start-up: the store refuses to save (logged once by the caller, not again at every knob save).
    void save_refused(std::string problem) { in_.last_save_problem = std::move(problem); }

private:
    friend struct LiveTuningAccess;  // live_tuning.cpp reaches these through it
    struct Internals {
        std::optional<params::ConfigWatcher> watcher;
        std::vector<io::Knob> knobs;
        io::GoneChips gone_chips;  // an unplugged chip is one warning for all its knobs
        std::vector<io::KnobAction> actions;
        bool layers_changed = false;              // a layer changed; Params is not yet its composition
        const char* change_reason = "";           // for the log line
        std::string schedule_reason;              // change_reason of the last SetSchedule points here
        std::optional<std::int64_t> apply_at_ns;  // wall.clock = "realtime": as a remote message asked
        bool state_dirty = false;                 // the knob state has changes not on disk
        std::string last_save_problem;            // logged once; not again until a save works
        double last_knob_change = 0;  // a failed save counts as a change: tried again a delay later
        double last_step = 0;         // the time live_tuning_step last ran
        std::uint64_t config_generation = 0;
        // Writes `state` off the frame thread; declared after it, so it is stopped before the store dies.
        std::unique_ptr<BackgroundJob<Result<void>>> saver = std::make_unique<BackgroundJob<Result<void>>>();
    } in_;
};

// Creates the knobs of the current config (on `tuning.gpio`, when there are any) and starts watching
// the config file. Call once, before the frame loop.
void start_live_tuning(LiveTuning& tuning);
// Reads the config file and the preset folders again; an invalid file is logged (file:line and why) and the
// last good configuration keeps running. Returns true when the new file was applied.
bool reload_config(LiveTuning& tuning);
// One input-stage step at time `now`: the inbox's requests in order, config changes, knob events, the
// delayed state save, and the recomposed `params` when a layer changed (logged as one line naming what
// changed). With wall.clock = "realtime" a changed layer is left pending for synced_changes_system, which
// applies it at the same step on every screen of a wall.
void live_tuning_step(TuningInbox& inbox, LiveTuning& tuning, params::Params& params, double now);

// wall.clock = "realtime": the change waiting for the wall (systems/tuning/synced_changes.hpp), if any:
// why (for the log) and when a remote message asked for it to apply.
struct PendingChange {
    const char* reason;
    std::optional<std::int64_t> apply_at_ns;
};
std::optional<PendingChange> pending_change(const LiveTuning& tuning);
// Applies the pending change now (Params becomes the layers' composition; one log line).
void apply_pending_change(LiveTuning& tuning, params::Params& params);
// A schedule transition forgets the knob values set while `entry` was active (ParamLayers::
// clear_knobs_set_by), and the saved state forgets them too. True when a value was forgotten.
bool forget_knobs_set_by(LiveTuning& tuning, int entry);
// Makes `params` the layers' composition now and logs one line: "REASON: rain.intensity 0.3 -> 0.5 (knob)".
void apply_layers(LiveTuning& tuning, params::Params& params, std::string_view reason);
// Input stage: live_tuning_step at the monotonic time now.
void live_tuning_system(TuningInbox& inbox, LiveTuning& tuning, params::Params& params);
// Hands the knob state to the saver thread when it has unsaved changes (the delayed save, the "save"
// button); the result is logged by a later live_tuning_step. Never waits for the disk.
void start_state_save(LiveTuning& tuning);
// Waits for a save in progress and logs its result (tests use it to see what a save did).
void finish_state_save(LiveTuning& tuning);
// The exit stage: waits for a save in progress, then writes the knob state now if it has changes that
// are not on disk yet. Waiting is fine here: the frame loop has ended.
void save_state(LiveTuning& tuning);

// Inserts the resource and the TuningInbox, starts it (start_live_tuning), adds live_tuning_system to the
// input stage and save_state to the exit stage.
Result<void> add_live_tuning(ecs::World& world, ecs::Schedule& schedule, LiveTuning tuning);

}  // namespace puddle::systems
