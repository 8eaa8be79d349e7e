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
//   simulate: begin step, drops, wave step               (once per fixed step; pulse drops only)
//   render:   surface | analytic ripples | grid drops    (the puddle's surface, by drops.model)
//             puddle | ocean | street                    (by scene.kind)
//             rain overlay                               (overlay.rain)
// Each system returns early when the parameters do not choose it, so a changed scene.kind or
// drops.model switches the look on the next frame; the pipelines of the look chosen at start-up are
// built here (errors stop start-up), others on first use.
Result<void> add_puddle_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
