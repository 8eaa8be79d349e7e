#pragma once
// The simulation clock: double-precision time and a fixed-step accumulator, so the number of wave steps
// per simulated second never depends on the display's frame rate.

#include <cstdint>

#include "ecs/frame_time.hpp"
#include "params/param_store.hpp"
#include "systems/common/output_power.hpp"

namespace puddle::systems {

struct FrameClock {
    double accumulator = 0.0;  // time not yet simulated
    double step_seconds = 1.0 / 60.0;
    double sim_time = 0.0;  // time of the step being simulated (advanced by begin_step)
    std::uint64_t step_index = 0;
    // sim_time = epoch_time + (step_index - epoch_step) * step_seconds: a product, not a running sum, so
    // months of steps lose no precision. The epoch moves only when the step rate changes.
    double epoch_time = 0.0;
    std::uint64_t epoch_step = 0;
    int steps_due = 0;             // simulate-stage runs this frame
    int max_steps_per_frame = 16;  // a stalled frame drops time rather than spiralling
    std::uint64_t dropped_steps = 0;
    // The simulation starts again from a flat field at the next step whenever this changes (a wall screen
    // joining the wall clock or re-syncing, systems/clock/wall_steps.hpp); the wave system clears its field
    // once per change.
    std::uint64_t field_generation = 0;
};

// Input stage, with wall.clock = "frame": turns this frame's time into steps_due at
// wave.steps_per_second. (With "realtime" the wall clock sets them: systems/clock/wall_steps.hpp.)
void frame_clock_system(const ecs::FrameTime& time, const params::Params& params, FrameClock& clock);
// Input stage, after frame_clock_system (wall.clock = "frame"): while the output is off the due steps are
// counted as done without running (no GPU work), so sim_time keeps up with the clock and the picture comes
// back at the current time, not where it stopped.
void hold_steps_while_off(const OutputPower& power, FrameClock& clock);
// First simulate-stage system: advances sim_time by one step.
void begin_step_system(FrameClock& clock);

}  // namespace puddle::systems
