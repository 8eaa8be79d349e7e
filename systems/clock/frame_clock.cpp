#include "systems/clock/frame_clock.hpp"

#include <cmath>

namespace puddle::systems {

void frame_clock_system(const ecs::FrameTime& time, const params::Params& params, FrameClock& clock) {
    using params::ParamId;
    const double step = 1.0 / static_cast<double>(params.get<ParamId::wave_steps_per_second>());
    if (step != clock.step_seconds) {
        clock.epoch_time = clock.sim_time;
        clock.epoch_step = clock.step_index;
        clock.step_seconds = step;
    }
    clock.accumulator += time.dt_seconds;
    // A step is due once the accumulator holds a whole step; the tolerance absorbs the rounding of
    // adding many small frame times, so 288 frames of 1/144 s are exactly 120 steps of 1/60 s.
    const double steps = std::floor(clock.accumulator / clock.step_seconds + 1e-6);
    int due = static_cast<int>(steps);
    clock.accumulator = std::max(0.0, clock.accumulator - steps * clock.step_seconds);
    if (due > clock.max_steps_per_frame) {
        clock.dropped_steps += static_cast<std::uint64_t>(due - clock.max_steps_per_frame);
        due = clock.max_steps_per_frame;
    }
    clock.steps_due = due;
}

void hold_steps_while_off(const OutputPower& power, FrameClock& clock) {
    if (power.on || clock.steps_due == 0) return;
    clock.step_index += static_cast<std::uint64_t>(clock.steps_due);
    clock.sim_time =
        clock.epoch_time + static_cast<double>(clock.step_index - clock.epoch_step) * clock.step_seconds;
    clock.steps_due = 0;
}

void begin_step_system(FrameClock& clock) {
    ++clock.step_index;
    clock.sim_time =
        clock.epoch_time + static_cast<double>(clock.step_index - clock.epoch_step) * clock.step_seconds;
}

}  // namespace puddle::systems
