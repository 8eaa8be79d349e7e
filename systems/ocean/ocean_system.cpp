#include "systems/ocean/ocean_system.hpp"

#include <algorithm>
#include <numbers>

#include "render/shader_phase.hpp"
#include "render/view_basis.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {
gpu::PipelineDesc ocean_desc(params::OceanMethod method) {
    if (method == params::OceanMethod::reference)
        return {.label = "ocean (reference march)", .vertex = "view_window.vert", .fragment = "ocean.frag"};
    return {.label = "ocean",
            .vertex = "view_window.vert",
            .fragment = "ocean.frag",
            .defines = {"OCEAN_SECANT"}};
}
}  // namespace

OceanTime ocean_time(double seconds, double speed) {
    OceanTime ot;
    double frequency = 0.16;  // ocean.frag's octave 0
    for (std::size_t i = 0; i < ot.shift.size(); ++i, frequency *= 2.0) {
        const double forward = speed * frequency, backward = -0.8 * forward;
        const render::LatticeShift f = render::lattice_shift(seconds, forward),
                                   b = render::lattice_shift(seconds, backward);
        ot.shift[i] = {f.fraction, render::periodic_phase(seconds, forward, std::numbers::pi), b.fraction,
                       render::periodic_phase(seconds, backward, std::numbers::pi)};
        ot.cells[i] = {f.cells, b.cells};
    }
    return ot;
}

OceanRenderer::OceanRenderer()
    : pass(ocean_desc(params::OceanMethod::secant)), reference(ocean_desc(params::OceanMethod::reference)) {}

void ocean_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                  OceanRenderer& ocean, const RenderTarget& target) {
    const bool reference = params.get<ParamId::ocean_method>() == params::OceanMethod::reference;
    FullscreenPass& chosen = reference && ocean.reference.request(device) ? ocean.reference : ocean.pass;
    chosen.draw(device, params, target, gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
        const render::ViewBasis cam = render::view_basis(
            params.get<ParamId::ocean_camera_position>(), params.get<ParamId::ocean_camera_target>(),
            params.get<ParamId::camera_fov>(), target.view.view_aspect(target.target.size));
        const OceanTime ot = ocean_time(clock.sim_time, params.get<ParamId::ocean_speed>());
        pass.set("u_octave_shift", std::span<const glm::vec4>(ot.shift))
            .set("u_octave_cells", std::span<const glm::ivec2>(ot.cells))
            .set("u_cam_forward", cam.forward)
            .set("u_cam_right", cam.right)
            .set("u_cam_up", cam.up)
            .set("u_cam_scale", cam.scale);
    });
}

void add_ocean_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& ocean = world.insert_resource<OceanRenderer>();
    world.resource<Looks>().entries.push_back(fullscreen_look(Scene::ocean, ocean.pass));
    schedule.add(ecs::Stage::Render, "ocean", ocean_system).run_if(look_is(Scene::ocean)).run_if(output_on());
}

}  // namespace puddle::systems
