#pragma once
// Whether the picture is on: the display power as applied this frame (systems/display/display_power.hpp
// switches it when display.power changes). While off no pass runs: the render systems, the output canvas and
// the simulation's GPU steps wait on output_on(), the simulation clock keeps time without stepping, and the
// frame loop sleeps in the present stage.

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"

namespace puddle::systems {

// Resource (inserted by the display plugin, systems/display/display_plugin.hpp).
struct OutputPower {
    bool on = true;
    // Window and headless have no output to switch off: the frame that goes off is cleared to black and
    // presented once; then nothing is presented until the picture is back.
    bool black_frame_pending = false;
};

// Run condition: the picture is on.
inline ecs::RunCondition output_on() {
    return {"output on", [](ecs::World& w) { return w.resource<OutputPower>().on; }};
}

}  // namespace puddle::systems
