#pragma once
// puddle --screenshot-at TIME (video walls, docs/video-walls.md): with wall.clock = "realtime", the run
// holds its wave field at the step that wall time TIME falls in (systems/clock/wall_steps.hpp, stop_step),
// renders that step once more, writes it and ends. Every screen of a wall given the same TIME writes the
// same step, so their pictures can be laid side by side to check the wall's alignment and bezels.

#include <cstdint>

#include "ecs/world.hpp"
#include "util/result.hpp"

namespace puddle::app {

struct WallScreenshot {
    std::int64_t at_ns = 0;  // TIME, nanoseconds since the Unix epoch
    std::int64_t step = 0;   // the wave step TIME falls in
};

// Sets the stop step in `world`'s WallSteps. Errors (exit code 2): wall.clock is not "realtime", the
// engine has no wall clock (no puddle feature), or TIME is not a time from now to a day ahead.
Result<WallScreenshot> arm_wall_screenshot(ecs::World& world, double at_seconds);

// True when the next frame is the one to capture: the frame clock stands at the step. An error (exit code
// 1) once the wall clock is 5 s past TIME without reaching it (a screen that warms up too slowly, or
// whose output is off): a later frame would be another step, not the wall's.
Result<bool> wall_screenshot_due(ecs::World& world, const WallScreenshot& shot);

}  // namespace puddle::app
