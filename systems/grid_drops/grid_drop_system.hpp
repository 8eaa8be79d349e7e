#pragma once
// Grid-sampled drops (REFERENCE.md section 5), the puddle's drops when drops.model = grid: the field is
// cut into square cells with one drop each, and every texel looks at its 3x3 cells only, so a frame
// costs the same at 10 or 1000 drops per second (grid_drops.frag writes the puddle's surface texture).
//
// grid.drops_per_second * grid.cycle drops are alive at once, one per cell, so that is the cell count.

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/output_power.hpp"
#include "systems/water/surface_system.hpp"

namespace puddle::systems {

// Resource.
struct GridDrops {
    render::SinglePipelineCache pass;
};

// Cell edge in field texels for the current parameters.
float grid_cell_texels(const params::Params& params, int field_resolution);

// reach 1 is the technique (3x3 cells); tests build reach 2 (5x5) to show nothing is lost outside 3x3.
Result<void> prepare_grid_drops(gpu::Device& device, const Surface& surface, GridDrops& grid, int reach = 1);
// Starts building the reach-1 pipeline off the frame thread (systems/common/look_switch.hpp); true once
// ready.
bool request_grid_drops(gpu::Device& device, const Surface& surface, GridDrops& grid);

// Writes the surface for simulated time `now`, once the pipeline is built; only_cell >= 0 isolates one
// cell's drop (tests).
void grid_drop_pass(gpu::Device& device, const params::Params& params, double now, const GridDrops& grid,
                    Surface& surface, glm::ivec2 only_cell = {-1, -1});

// Render stage, before the puddle pass, while the puddle with grid drops is the look shown.
void grid_drop_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                      GridDrops& grid, Surface& surface);

// The grid drops' plugin: their resource, their entry in Looks (the puddle with drops.model = grid) and
// their render system. Needs the Surface and Looks resources.
void add_grid_drops_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
