#pragma once
// The puddle feature: its resources and its systems, in order. This is the one place the order of the
// puddle's systems is written (Bevy's plugin build()); app::Engine runs it after its display plugin,
// and tests/app/engine_test.cpp pins the resulting schedule.

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Needs the resources gpu::Device, params::Params and RenderTarget in the world. Loads the environment
// and ground (errors: exit code 3), builds the GPU resources and registers:
//   input:    synced changes (when LiveTuning is installed), wall steps | frame clock (wall.clock),
//             hold steps while off, wave rebuild, environment reload, look switch, camera feed
//   simulate: begin step, drops, wave               (once per fixed step; if the wave field is in use)
//   render:   surface | analytic ripples | grid drops (the puddle's surface, by the drops shown)
//             camera environment
//             puddle | ocean | street               (if look is ...: the look on screen, ShownLook)
//             rain overlay                          (overlay.rain)
// A newly chosen look is shown once the look switch has its pipelines (built off the frame thread);
// the pipelines of the look chosen at start-up are built here, so a broken shader stops start-up.
Result<void> add_puddle_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
