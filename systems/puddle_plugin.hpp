#pragma once
// The puddle feature: its resources and its systems, in order. This is the one place the order of the
// puddle's systems is written (Bevy's plugin build()).

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Needs the resources gpu::Device, params::Params and RenderTarget in the world. Loads the environment
// and ground (errors: exit code 3), builds the GPU resources and registers:
//   input:    frame clock, wave field rebuild (when wave.resolution or wave.float_field change)
//   simulate: begin step, drops, wave step               (once per fixed step)
//   render:   surface, puddle
Result<void> add_puddle_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
