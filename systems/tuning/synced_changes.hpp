#pragma once
// Changes in step (wall.clock = "realtime"): a config reload, a remote message or a knob turn
// that live tuning has read is not applied in the frame that read it, which differs from screen to screen,
// but at the step of the next wall.change_period boundary plus one period (change_boundary), or at the
// time a remote message asks for (LiveTuning::apply_at_ns). Every screen that read the change within the
// same period switches at the same step: the frame clock simulates up to the step before it, the change is
// applied, and the step itself runs with it. Two reads on either side of a period boundary land one period
// apart; a remote message's apply_at has no such edge. An apply_at in the past, or more than an hour ahead
// (max_apply_ahead_ns: a mistyped time would hold this and every later change), is logged as a warning
// and the change lands at the boundary instead.

#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/common/output_power.hpp"
#include "systems/tuning/live_tuning.hpp"

namespace puddle::systems {

inline constexpr std::int64_t max_apply_ahead_ns = 3600 * ns_per_second;

// Input stage, with wall.clock = "realtime", after live tuning and before wall steps: applies the layers'
// pending change (LiveTuning::layers_changed) once the next step to simulate is its step, and until then
// holds that step back (WallSteps::change_step). While the output is off no step is simulated, so there
// the change applies once the clock reaches its step (it may turn the output back on). Logs when the change
// will apply.
void synced_changes_system(const WallClock& wall, const FrameClock& clock, const OutputPower& power,
                           LiveTuning& tuning, params::Params& params, WallSteps& steps);

}  // namespace puddle::systems
