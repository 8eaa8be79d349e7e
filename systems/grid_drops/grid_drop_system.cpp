#include "systems/grid_drops/grid_drop_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/param_uniforms.hpp"

namespace puddle::systems {

using params::ParamId;

float grid_cell_texels(const params::Params& params, int field_resolution) {
    const double cells = std::max(1.0, static_cast<double>(params.get<ParamId::grid_drops_per_second>()) *
                                           static_cast<double>(params.get<ParamId::grid_cycle>()));
    return static_cast<float>(field_resolution / std::sqrt(cells));
}

namespace {
gpu::PipelineDesc grid_drops_desc(const Surface& surface, int reach) {
    std::vector<std::string> defines{fmt::format("GRID_REACH {}", reach)};
    if (surface.unorm) defines.emplace_back("SURFACE_UNORM");
    return {.label = "grid drops", .fragment = "grid_drops.frag", .defines = defines};
}
}  // namespace

Result<void> prepare_grid_drops(gpu::Device& device, const Surface& surface, GridDrops& grid, int reach) {
    return grid.pass.ensure(device, {}, [&] { return grid_drops_desc(surface, reach); });
}

bool request_grid_drops(gpu::Device& device, const Surface& surface, GridDrops& grid) {
    return grid.pass.request(device, {}, [&] { return grid_drops_desc(surface, 1); }) != nullptr;
}

void grid_drop_pass(gpu::Device& device, const params::Params& params, double now, const GridDrops& grid,
                    Surface& surface, glm::ivec2 only_cell) {
    // Cycle count and fraction split in double: a float time would lose the fraction after weeks.
    const double cycles = now / static_cast<double>(params.get<ParamId::grid_cycle>());
    const double base = std::floor(cycles);
    const render::BuiltPipeline* built = grid.pass.find({});
    if (!built) return;
    auto pass = device.begin_pass({.label = "grid drops",
                                   .target = {&surface.texture, {surface.resolution, surface.resolution}},
                                   .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(built->pipeline);
    render::set_param_uniforms(pass, built->params, params);
    pass.set("u_cell_texels", grid_cell_texels(params, surface.resolution))
        // Modulo 2^32, handed over as the bits of the shader's uint: its uint sum with the cell's own
        // cycle then wraps exactly where this count does, so no drop jumps at any uptime.
        .set("u_cycle_base", static_cast<int>(static_cast<std::uint32_t>(std::fmod(base, 4294967296.0))))
        .set("u_cycle_fraction", static_cast<float>(cycles - base))
        .set("u_seed", params.get<ParamId::rain_seed>())
        .set("u_only_cell", only_cell);
    pass.draw_fullscreen();
}

void grid_drop_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                      GridDrops& grid, Surface& surface) {
    if (!request_grid_drops(device, surface, grid)) return;  // a failure is logged once, then nothing drawn
    grid_drop_pass(device, params, clock.sim_time, grid, surface);
}

void add_grid_drops_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& grid = world.insert_resource<GridDrops>();
    const Surface& surface = world.resource<Surface>();
    world.resource<Looks>().entries.push_back(
        {.scene = Scene::puddle,
         .drops = DropModel::grid,
         .prepare = [&surface, &grid](gpu::Device& d) { return prepare_grid_drops(d, surface, grid); },
         .request = [&surface, &grid](gpu::Device& d) { return request_grid_drops(d, surface, grid); }});
    schedule.add(ecs::Stage::Render, "grid drops", grid_drop_system)
        .run_if(drops_are(DropModel::grid))
        .run_if(output_on());
}

}  // namespace puddle::systems
