#include "systems/puddle_plugin.hpp"

#include <spdlog/spdlog.h>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/camera_environment.hpp"
#include "systems/camera_system.hpp"
#include "systems/analytic_ripple_system.hpp"
#include "systems/drop_system.hpp"
#include "systems/environment_system.hpp"
#include "systems/frame_clock.hpp"
#include "systems/grid_drop_system.hpp"
#include "systems/look_switch.hpp"
#include "systems/ocean_system.hpp"
#include "systems/rain_overlay_system.hpp"
#include "systems/render_system.hpp"
#include "systems/scene_select.hpp"
#include "systems/street_system.hpp"
#include "systems/surface_system.hpp"
#include "systems/wave_system.hpp"

namespace puddle::systems {

using params::ParamId;
using params::Params;

namespace {

// Both or neither: a surface that fails to build keeps the old field too (their sizes must match).
Result<void> build_field_and_surface(ecs::World& world) {
    auto& device = world.resource<gpu::Device>();
    WaveField new_field;
    Surface new_surface;
    if (auto r = build_wave_field(device, world.resource<Params>(), new_field); !r) return r;
    if (auto r = build_surface(device, new_field, new_surface); !r) return r;
    auto& field = world.resource<WaveField>() = std::move(new_field);
    world.resource<Surface>() = std::move(new_surface);
    spdlog::info("wave: {}x{} field, {} ({} steps/s)", field.resolution, field.resolution,
                 field.fixed_point ? "fixed-point RG32I (no float render targets)" : "float RG32F",
                 world.resource<Params>().f(ParamId::wave_steps_per_second));
    return {};
}

// Input stage: a new resolution or field format needs new textures; the old field is dropped. One that
// cannot be made (too big for GPU memory) logs one line and keeps the old field, until the values change.
void wave_rebuild_system(ecs::World& world) {
    const Params& params = world.resource<Params>();
    WaveField& field = world.resource<WaveField>();
    const bool want_fixed = !(params.b(ParamId::wave_float_field) &&
                              world.resource<gpu::Device>().caps().float_render_targets);
    const WaveField::Request wanted{params.i(ParamId::wave_resolution), want_fixed};
    if (field.resolution == wanted.resolution && field.fixed_point == want_fixed) {
        field.requested = {};  // back to what is shown: a later edit to the failed values tries again
        return;
    }
    if (wanted == field.requested) return;
    if (auto r = build_field_and_surface(world); !r) {
        spdlog::error("{} (keeping the {}x{} field)", r.error().message, field.resolution, field.resolution);
        field.requested = wanted;
    }
}

// The puddle's surface comes from the wave field only with the pulse drops; analytic and grid drops
// write it themselves, and the other scenes need no simulation at all.
bool wave_field_in_use(ecs::World& w) {
    const ShownLook& look = w.resource<ShownLook>();
    return look.scene == Scene::Puddle && look.drops == DropModel::Pulse;
}

bool shown(ecs::World& w, Scene scene) { return w.resource<ShownLook>().scene == scene; }
bool shown(ecs::World& w, DropModel drops) {
    return shown(w, Scene::Puddle) && w.resource<ShownLook>().drops == drops;
}

// Start-up builds the pipelines of the look the config chose, so a broken shader stops start-up with its
// message; looks chosen later are built by their systems on first use.
Result<void> prepare_selected_look(ecs::World& world) {
    auto& device = world.resource<gpu::Device>();
    const Params& params = world.resource<Params>();
    const Surface& surface = world.resource<Surface>();
    if (params.b(ParamId::overlay_rain))
        if (auto r = prepare_rain_overlay(device, world.resource<RainOverlay>()); !r) return r;
    switch (selected_scene(params)) {
        case Scene::Ocean: return prepare_ocean(device, world.resource<OceanRenderer>());
        case Scene::Street: return prepare_street(device, world.resource<StreetRenderer>());
        case Scene::Puddle: break;
    }
    switch (selected_drop_model(params)) {
        case DropModel::Analytic: return prepare_analytic_ripples(device, surface, world.resource<AnalyticRipples>());
        case DropModel::Grid: return prepare_grid_drops(device, surface, world.resource<GridDrops>());
        case DropModel::Pulse: break;
    }
    return {};
}

}  // namespace

Result<void> add_puddle_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& device = world.resource<gpu::Device>();
    const Params& params = world.resource<Params>();

    auto& env = world.insert_resource<Environment>();
    if (auto r = load_environment(device, params, env); !r) return r;
    world.insert_resource<EnvironmentReload>();
    auto& ground = world.insert_resource<Ground>();
    if (auto r = load_ground(device, params, ground); !r) return r;
    spdlog::info("ground: {}", ground.source);
    world.insert_resource<CameraEnvironment>();
    if (auto r = open_camera_feed(world.insert_resource<CameraFeed>(), params); !r) return r;

    world.insert_resource<FrameClock>();
    world.insert_resource<DropSlots>();
    world.insert_resource<LiveDrops>();
    world.storage<Drop>().reserve(max_drops);
    world.insert_resource<WaveField>();
    world.insert_resource<Surface>();
    if (auto r = build_field_and_surface(world); !r) return r;
    if (auto r = build_puddle_renderer(device, world.resource<Surface>(), env, params,
                                       world.insert_resource<PuddleRenderer>());
        !r)
        return r;
    world.insert_resource<AnalyticRipples>();
    world.insert_resource<GridDrops>();
    world.insert_resource<OceanRenderer>();
    world.insert_resource<StreetRenderer>();
    world.insert_resource<RainOverlay>();
    if (auto r = prepare_selected_look(world); !r) return r;
    world.insert_resource<ShownLook>(selected_look(params));

    schedule.set_step_counter([](ecs::World& w) { return w.resource<FrameClock>().steps_due; });

    schedule.add_system(ecs::Stage::Input, "frame clock", [](ecs::World& w) {
        frame_clock_system(w.resource<FrameClock>(), w.resource<Params>());
    });
    schedule.add_system(ecs::Stage::Input, "wave rebuild", wave_rebuild_system);
    schedule.add_system(ecs::Stage::Input, "environment reload", environment_reload_system);
    schedule.add_system(ecs::Stage::Input, "look switch", [](ecs::World& w) {
        look_switch_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<Surface>(),
                           w.resource<OceanRenderer>(), w.resource<StreetRenderer>(),
                           w.resource<AnalyticRipples>(), w.resource<GridDrops>(), w.resource<ShownLook>());
    });
    schedule.add_system(ecs::Stage::Input, "camera feed", [](ecs::World& w) {
        camera_feed_system(w.resource<CameraFeed>(), w.resource<Params>(), w.resource<FrameClock>(),
                           w.resource<gpu::Device>(), w.resource<CameraEnvironment>());
    });

    schedule.add_system(ecs::Stage::Simulate, "begin step",
                        [](ecs::World& w) { begin_step_system(w.resource<FrameClock>()); });
    schedule.add_system(ecs::Stage::Simulate, "drops", [](ecs::World& w) {
        if (!wave_field_in_use(w)) return;
        drop_system(w.resource<Params>(), w.resource<FrameClock>(), w, w.resource<DropSlots>(),
                    w.resource<LiveDrops>());
    });
    schedule.add_system(ecs::Stage::Simulate, "wave", [](ecs::World& w) {
        if (!wave_field_in_use(w)) return;
        wave_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<LiveDrops>(),
                    w.resource<WaveField>());
    });

    schedule.add_system(ecs::Stage::Render, "surface", [](ecs::World& w) {
        if (!wave_field_in_use(w)) return;
        surface_system(w.resource<gpu::Device>(), w.resource<WaveField>(), w.resource<Surface>());
    });
    schedule.add_system(ecs::Stage::Render, "camera environment", [](ecs::World& w) {
        camera_environment_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<Environment>(),
                                  w.resource<CameraEnvironment>());
    });
    schedule.add_system(ecs::Stage::Render, "analytic ripples", [](ecs::World& w) {
        if (!shown(w, DropModel::Analytic)) return;
        analytic_ripple_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<FrameClock>(),
                               w.resource<AnalyticRipples>(), w.resource<Surface>());
    });
    schedule.add_system(ecs::Stage::Render, "grid drops", [](ecs::World& w) {
        if (!shown(w, DropModel::Grid)) return;
        grid_drop_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<FrameClock>(),
                         w.resource<GridDrops>(), w.resource<Surface>());
    });
    schedule.add_system(ecs::Stage::Render, "puddle", [](ecs::World& w) {
        if (!shown(w, Scene::Puddle)) return;
        render_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<Surface>(),
                      w.resource<Environment>(), w.resource<Ground>(), w.resource<PuddleRenderer>(),
                      w.resource<RenderTarget>(), w.resource<CameraEnvironment>().reflection());
    });
    schedule.add_system(ecs::Stage::Render, "ocean", [](ecs::World& w) {
        if (!shown(w, Scene::Ocean)) return;
        ocean_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<FrameClock>(),
                     w.resource<OceanRenderer>(), w.resource<RenderTarget>());
    });
    schedule.add_system(ecs::Stage::Render, "street", [](ecs::World& w) {
        if (!shown(w, Scene::Street)) return;
        street_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<FrameClock>(),
                      w.resource<StreetRenderer>(), w.resource<RenderTarget>());
    });
    schedule.add_system(ecs::Stage::Render, "rain overlay", [](ecs::World& w) {
        rain_overlay_system(w.resource<gpu::Device>(), w.resource<Params>(), w.resource<FrameClock>(),
                            w.resource<RainOverlay>(), w.resource<RenderTarget>());
    });
    return {};
}

}  // namespace puddle::systems
