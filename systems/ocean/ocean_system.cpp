#include "systems/ocean/ocean_system.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <numbers>

#include "render/shader_phase.hpp"
#include "render/view_basis.hpp"
#include "systems/ocean/ocean_height_map.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

gpu::PipelineDesc ocean_desc(const char* label, std::vector<std::string> defines,
                             std::vector<std::string> textures = {}) {
    return {.label = label,
            .vertex = "view_window.vert",
            .fragment = "ocean.frag",
            .defines = std::move(defines),
            .textures = std::move(textures)};
}

// The passes start-up builds: the map's where the GPU can render it, and the secant search.
template <class Each>
bool each_prepared_pass(gpu::Device& device, OceanRenderer& ocean, Each&& each) {
    bool all = each(ocean.secant);
    if (device.caps().half_float_render_targets) {
        const bool height = each(ocean.height), slope = each(ocean.slope), mapped = each(ocean.mapped);
        all = all && height && slope && mapped;
    }
    return all;
}

// Sets the uniforms every ocean pass reads of the camera and of time.
void set_view_and_time(gpu::RenderPass& pass, const render::ViewBasis& cam, const OceanTime& ot) {
    pass.set("u_octave_shift", std::span<const glm::vec4>(ot.shift))
        .set("u_octave_cells", std::span<const glm::ivec2>(ot.cells))
        .set("u_cam_forward", cam.forward)
        .set("u_cam_right", cam.right)
        .set("u_cam_up", cam.up)
        .set("u_cam_scale", cam.scale);
}

// Makes the map's textures for `layout` unless they have its size; false when the driver refused one
// (said once; the ocean then stays with the secant search).
bool ensure_map(gpu::Device& device, OceanRenderer& ocean, const OceanHeightMapLayout& layout) {
    if (ocean.map && ocean.map.width() == layout.size.x && ocean.map.height() == layout.size.y) return true;
    for (gpu::Texture* texture : {&ocean.heights, &ocean.map}) {
        // The heights in full floats where the GPU renders them: the slopes are differences of heights
        // a texel apart, which half floats (about 0.001 at a height of 1) would cut into steps.
        const bool full = texture == &ocean.heights && device.caps().float_render_targets;
        auto made =
            device.create_texture({.label = texture == &ocean.map ? "ocean height map" : "ocean heights",
                                   .format = full ? gpu::TextureFormat::RG32F : gpu::TextureFormat::RGBA16F,
                                   .width = layout.size.x,
                                   .height = layout.size.y,
                                   .render_target = true});
        if (!made) {
            spdlog::warn(
                "ocean: the height map could not be made ({}); the ocean computes its waves per "
                "pixel (ocean.method = \"secant\") from now on, at several times the cost",
                made.error().message);
            ocean.heights = {};
            ocean.map = {};
            ocean.map_refused = true;
            return false;
        }
        *texture = std::move(made).value();
    }
    if (ocean.map_sampler.id() == 0) {
        ocean.nearest = device.create_sampler(
            {.label = "ocean heights", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
        ocean.map_sampler = device.create_sampler(
            {.label = "ocean height map", .min = gpu::Filter::Linear, .mag = gpu::Filter::Linear});
    }
    return true;
}

}  // namespace

OceanTime ocean_time(double seconds, double speed) {
    OceanTime ot;
    double frequency = 0.16;  // ocean_waves.glsl's octave 0
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
    : height({.label = "ocean height map", .vertex = "view_window.vert", .fragment = "ocean_height.frag"}),
      slope({.label = "ocean slopes",
             .vertex = "view_window.vert",
             .fragment = "ocean_slope.frag",
             .textures = {"u_heights"}}),
      mapped(ocean_desc("ocean", {"OCEAN_HEIGHT_MAP"}, {"u_height_map"})),
      secant(ocean_desc("ocean (secant search)", {"OCEAN_SECANT"})),
      reference(ocean_desc("ocean (reference march)", {})) {}

void ocean_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                  OceanRenderer& ocean, const RenderTarget& target) {
    const glm::vec3 eye = params.get<ParamId::ocean_camera_position>();
    const render::ViewBasis cam =
        render::view_basis(eye, params.get<ParamId::ocean_camera_target>(), params.get<ParamId::camera_fov>(),
                           target.view.view_aspect(target.target.size));
    const OceanTime ot = ocean_time(clock.sim_time, params.get<ParamId::ocean_speed>());
    const auto method = params.get<ParamId::ocean_method>();

    const bool map_possible = method == params::OceanMethod::height_map &&
                              device.caps().half_float_render_targets && !ocean.map_refused &&
                              ocean.height.request(device) && ocean.slope.request(device) &&
                              ocean.mapped.request(device);
    if (map_possible) {
        const OceanHeightMapLayout layout = ocean_height_map_layout(
            cam, eye,
            ocean_highest_wave(params.get<ParamId::ocean_height>(), params.get<ParamId::ocean_octaves>()),
            target.view, target.target.size);
        if (!layout.empty() && ensure_map(device, ocean, layout)) {
            const render::ViewWindow map_window{.origin = layout.origin, .extent = layout.extent};
            ocean.height.draw(device, params, {.target = {&ocean.heights, layout.size}, .view = map_window},
                              gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
                                  set_view_and_time(pass, cam, ot);
                                  pass.set("u_map_plane", layout.plane)
                                      .set("u_texel_angle", ocean_texel_angle(cam, layout));
                              });
            ocean.slope.draw(device, params, {.target = {&ocean.map, layout.size}, .view = map_window},
                             gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
                                 set_view_and_time(pass, cam, ot);
                                 pass.set_texture(0, ocean.heights, ocean.nearest)
                                     .set("u_map_window", layout.uniform())
                                     .set("u_map_plane", layout.plane);
                             });
            ocean.mapped.draw(device, params, target, gpu::LoadOp::DontCare, [&](gpu::RenderPass& pass) {
                set_view_and_time(pass, cam, ot);
                pass.set_texture(0, ocean.map, ocean.map_sampler)
                    .set("u_map_window", layout.uniform())
                    .set("u_map_plane", layout.plane);
            });
            return;
        }
    }
    const bool reference = method == params::OceanMethod::reference && ocean.reference.request(device);
    FullscreenPass& chosen = reference ? ocean.reference : ocean.secant;
    chosen.draw(device, params, target, gpu::LoadOp::DontCare,
                [&](gpu::RenderPass& pass) { set_view_and_time(pass, cam, ot); });
}

void add_ocean_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& ocean = world.insert_resource<OceanRenderer>();
    world.resource<Looks>().entries.push_back(
        {.scene = Scene::ocean,
         .prepare = [&ocean](gpu::Device& d) -> Result<void> {
             Result<void> result{};
             each_prepared_pass(d, ocean, [&](FullscreenPass& p) {
                 if (result) result = p.prepare(d);
                 return static_cast<bool>(result);
             });
             return result;
         },
         .request =
             [&ocean](gpu::Device& d) {
                 return each_prepared_pass(d, ocean, [&](FullscreenPass& p) { return p.request(d); });
             },
         .takes_rain_overlay = false});  // a clear day at sea, the sun out: falling rain would not belong
    schedule.add(ecs::Stage::Render, "ocean", ocean_system).run_if(look_is(Scene::ocean)).run_if(output_on());
}

}  // namespace puddle::systems
