#pragma once
// Time from the wall clock (wall.clock = "realtime"): the step a frame simulates up to is the
// one its vblank falls in, step_at(now + wall.latency) (systems/clock/wall_clock.hpp), so screens whose
// clocks agree show the same step, and the simulation stays a pure function of seed, parameters and step.
//
// The wave field carries history, so a screen that has none (start-up, the field coming back into use,
// or a gap it cannot simply catch up) joins by a warm-up: the field starts flat wall.warmup seconds
// before the clock's step and is simulated forward at most wall.catch_up_steps steps a frame until it
// reaches it. What it still differs from a screen that ran all along is what is left of the start:
// damping^(n/2) (warmup_residual). Frames keep being presented during a warm-up (the picture
// fast-forwards for warmup x steps_per_second / (catch_up_steps - 1) frames: 21 with the defaults), so
// the watchdog is pinged every frame.
//
// Clock steps: forward by up to the warm-up, the missed steps are caught up, catch_up_steps a frame, and
// the field is exactly that of a screen that never stopped; further forward, a re-sync as above. Back by
// up to a quarter second the screen holds its step until the clock is there again (it already simulated
// those steps); further back, a re-sync. While the output is off nothing is simulated, and waking counts
// as a forward step by the time it was off.
//
// A screen too slow for the wall's pace (its GPU simulates fewer than wave.steps_per_second steps a
// second) would warm up, fall further behind than the warm-up and re-sync, for ever. It is found by a
// re-sync for being behind that comes before the warm-up it restarts ever reached the clock's step: the
// screen then says once what pace it reached and what to lower, and falls back to the clock's time
// instead of its steps: each frame it skips to the clock's step and simulates at most
// behind_steps_per_frame of them, so frames keep coming and the ripples run on, no longer matching the
// other screens. A change of wave.resolution or wave.steps_per_second tries the wall's pace again.

#include <cstdint>
#include <optional>
#include <string>

#include "ecs/schedule.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/common/output_power.hpp"
#include "systems/common/shown_look.hpp"

namespace puddle::systems {

// A backward clock step this long or shorter is waited out rather than re-synced.
inline constexpr double max_hold_seconds = 0.25;

// Steps a frame at most on a screen that cannot keep the wall's pace.
inline constexpr int behind_steps_per_frame = 2;

// Resource.
struct WallSteps {
    bool joined = false;           // step_index follows the wall clock; false: the next frame joins
    bool field_in_use = false;     // the wave field was simulated last frame (the look needs it)
    std::int64_t target_step = 0;  // the step this frame's vblank falls in
    std::uint64_t resyncs = 0;     // warm-ups begun, joining at start-up included
    // Nonzero: a synced change (systems/tuning/synced_changes.hpp) applies at this step, so no frame
    // simulates it or a later one before the change is in Params.
    std::uint64_t change_step = 0;
    // Nonzero: no frame simulates past this step (puddle --screenshot-at: every screen of a wall stops on
    // the same step and writes it).
    std::int64_t stop_step = 0;
    bool sync_checked = false;  // the kernel's clock discipline was looked at (warned once if unsynchronised)

    // Since the last (re)start of the field: when, from which step, and whether a frame reached the
    // clock's step since (a warm-up that never does means the screen cannot keep the wall's pace).
    std::int64_t restart_ns = 0;
    std::uint64_t restart_step = 0;
    bool reached_clock = false;
    // The screen cannot keep the wall's pace at these settings (wave.resolution, steps per second): it
    // follows the clock's time, not its steps (see the header's comment).
    bool behind_the_wall = false;
    int behind_resolution = 0;
    double behind_rate = 0.0;
    bool behind_said = false;  // the warning is logged once a run; later times at debug level
};

// Input stage, with wall.clock = "realtime": sets the frame clock's steps_due (and, on a join or re-sync,
// its step index and field generation) from the wall clock. Logs one line per re-sync, and warns once
// when the kernel does not consider the clock synchronised (read_clock_sync).
void wall_steps_system(const WallClock& wall, const OutputPower& power, const ShownLook& look,
                       const params::Params& params, WallSteps& steps, FrameClock& clock);

// What keeps a wall's screens from matching however good their clocks are, as one line to log and for
// --check: a wall of several screens whose wall.clock is "frame" (each counts from its own start), or the
// realtime clock with wave.damping = 1 (a field that never forgets its start never converges). None
// otherwise.
std::optional<std::string> wall_timing_problem(const params::Params& params);

// "wall.clock is realtime" / "wall.clock is frame".
ecs::RunCondition wall_clock_is(params::WallClockMode mode);

}  // namespace puddle::systems
