#pragma once
// Resource: the time one frame advances, the schedule's one input from outside. Whoever runs frames
// sets it before each run (app::Engine::frame): the real time since the last frame, or a fixed step
// where runs must repeat exactly (headless, tests). Systems turn it into simulation steps
// (systems/clock/frame_clock.hpp) or their own clocks.

namespace puddle::ecs {

struct FrameTime {
    double dt_seconds = 0.0;  // >= 0, double so that months of frames lose no precision
};

}  // namespace puddle::ecs
