#pragma once
// The look switch (input stage, after live tuning): when the parameters choose another scene or drop
// model, it has that look's pipelines built off the frame thread (render::PipelineCache::request) and moves
// ShownLook to it in the first frame they are all ready. Until then the old look stays on screen and
// the frame loop keeps its pace and the watchdog ping (issue 15: no shader compile on the frame thread).
// A look whose pipeline fails to build is never switched to: its error is logged once and the old look
// stays, as with any bad live edit.

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/analytic_ripple_system.hpp"
#include "systems/grid_drop_system.hpp"
#include "systems/ocean_system.hpp"
#include "systems/scene_select.hpp"
#include "systems/street_system.hpp"
#include "systems/surface_system.hpp"

namespace puddle::systems {

void look_switch_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                        OceanRenderer& ocean, StreetRenderer& street, AnalyticRipples& ripples,
                        GridDrops& grid, ShownLook& shown);

}  // namespace puddle::systems
