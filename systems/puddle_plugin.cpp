#include "systems/puddle_plugin.hpp"

#include <spdlog/spdlog.h>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/analytic_ripple_system.hpp"
#include "systems/camera_environment.hpp"
#include "systems/camera_system.hpp"
#include "systems/capillary_step.hpp"
#include "systems/drop_system.hpp"
#include "systems/environment_system.hpp"
#include "systems/frame_clock.hpp"
#include "systems/grid_drop_system.hpp"
#include "systems/look_switch.hpp"
#include "systems/ocean_system.hpp"
#include "systems/output_power.hpp"
#include "systems/rain_overlay_system.hpp"
#include "systems/render_system.hpp"
#include "systems/scene_select.hpp"
#include "systems/street_system.hpp"
#include "systems/surface_system.hpp"
#include "systems/synced_changes.hpp"
#include "systems/wall_clock.hpp"
#include "systems/wall_steps.hpp"
#include "systems/wave_system.hpp"

namespace puddle::systems {

using params::ParamId;
using params::Params;

namespace {

// The pipelines, sampler and drop buffer of `from` handed to `to`, so that build_wave_field and
// build_surface keep them instead of making them again.
void hand_over_passes(WaveField& from, WaveField& to) {
    to.step_pipelines = std::move(from.step_pipelines);
    to.nearest = std::move(from.nearest);
    to.drops = std::move(from.drops);
}
void hand_over_passes(Surface& from, Surface& to) {
    to.pipelines = std::move(from.pipelines);
    to.field_sampler = std::move(from.field_sampler);
    to.sampler = std::move(from.sampler);
    to.tiled_sampler = std::move(from.tiled_sampler);
    to.marched_sampler = std::move(from.marched_sampler);
}

bool wants_fixed_point(const gpu::Device& device, const Params& params) {
    return !(params.get<ParamId::wave_float_field>() && device.caps().float_render_targets);
}

// Both or neither: a surface that fails to build keeps the old field too (their sizes must match). The
// compiled passes go with the new field and surface and come back on a failure, so a new resolution
// compiles nothing (fresh ones compiled both shaders again on the frame thread at every live edit).
Result<void> build_field_and_surface(gpu::Device& device, const Params& params, WaveField& field,
                                     Surface& surface) {
    WaveField new_field;
    Surface new_surface;
    hand_over_passes(field, new_field);
    hand_over_passes(surface, new_surface);
    auto built = build_wave_field(device, params, new_field);
    if (built) built = build_surface(device, new_field, new_surface);
    if (!built) {
        hand_over_passes(new_field, field);
        hand_over_passes(new_surface, surface);
        return built;
    }
    field = std::move(new_field);
    surface = std::move(new_surface);
    const char* encoding = field.fixed_point ? "fixed-point RG32I (no float render targets)" : "float RG32F";
    if (field.capillary)
        spdlog::info(
            "wave: {}x{} field, {}, capillary ripples over {:.2f} m ({:.1f} mm a texel, {} passes a "
            "step at {} steps/s)",
            field.resolution, field.resolution, encoding,
            static_cast<double>(params.get<ParamId::wave_size>()),
            1e3 * capillary_step(params,
                                 1.0 / static_cast<double>(params.get<ParamId::wave_steps_per_second>()))
                      .texel_m,
            capillary_step(params, 1.0 / static_cast<double>(params.get<ParamId::wave_steps_per_second>()))
                .substeps,
            static_cast<double>(params.get<ParamId::wave_steps_per_second>()));
    else
        spdlog::info("wave: {}x{} field, {}, the reference's wave equation ({} steps/s)", field.resolution,
                     field.resolution, encoding,
                     static_cast<double>(params.get<ParamId::wave_steps_per_second>()));
    return {};
}

// Input stage: a new resolution or field format needs new textures; the old field is dropped. One that
// cannot be made (too big for GPU memory) logs one line and keeps the old field, until the values change.
void wave_rebuild_system(gpu::Device& device, const Params& params, WaveField& field, Surface& surface) {
    const bool want_fixed = wants_fixed_point(device, params);
    const bool want_capillary = params.get<ParamId::wave_model>() == params::WaveModel::capillary;
    const WaveField::Request wanted{params.get<ParamId::wave_resolution>(), want_fixed, want_capillary};
    if (field.resolution == wanted.resolution && field.fixed_point == want_fixed &&
        field.capillary == want_capillary) {
        field.requested = {};  // back to what is shown: a later edit to the failed values tries again
        return;
    }
    if (wanted == field.requested) return;
    if (auto r = build_field_and_surface(device, params, field, surface); !r) {
        spdlog::error("{} (keeping the {}x{} field)", r.error().message, field.resolution, field.resolution);
        field.requested = wanted;
    }
}

// Start-up builds the pipelines of the look the config chose, so a broken shader stops start-up with its
// message; looks chosen later are built by their systems on first use.
Result<void> prepare_selected_look(ecs::World& world) {
    auto& device = world.resource<gpu::Device>();
    const Params& params = world.resource<Params>();
    const Surface& surface = world.resource<Surface>();
    if (params.get<ParamId::overlay_rain>())
        if (auto r = prepare_rain_overlay(device, world.resource<RainOverlay>()); !r) return r;
    switch (selected_scene(params)) {
        case Scene::ocean:
            return prepare_ocean(device, world.resource<OceanRenderer>());
        case Scene::street:
            return prepare_street(device, world.resource<StreetRenderer>());
        case Scene::puddle:
            break;
    }
    switch (selected_drop_model(params)) {
        case DropModel::analytic:
            return prepare_analytic_ripples(device, surface, world.resource<AnalyticRipples>());
        case DropModel::grid:
            return prepare_grid_drops(device, surface, world.resource<GridDrops>());
        case DropModel::pulse:
            break;
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
    if (!world.try_resource<WallClock>()) world.insert_resource<WallClock>();  // the schedule's, if installed
    world.insert_resource<WallSteps>();
    world.insert_resource<DropSlots>();
    world.insert_resource<LiveDrops>();
    world.storage<Drop>().reserve(max_drops);
    auto& field = world.insert_resource<WaveField>();
    auto& surface = world.insert_resource<Surface>();
    if (auto r = build_field_and_surface(device, params, field, surface); !r) return r;
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

    using ecs::Stage;
    using params::WallClockMode;
    if (world.try_resource<LiveTuning>())
        schedule.add(Stage::Input, "synced changes", synced_changes_system)
            .run_if(wall_clock_is(WallClockMode::realtime));
    schedule.add(Stage::Input, "wall steps", wall_steps_system)
        .run_if(wall_clock_is(WallClockMode::realtime));
    schedule.add(Stage::Input, "frame clock", frame_clock_system).run_if(wall_clock_is(WallClockMode::frame));
    schedule.add(Stage::Input, "hold steps while off", hold_steps_while_off);
    schedule.add(Stage::Input, "wave rebuild", wave_rebuild_system);
    schedule.add(Stage::Input, "environment reload", environment_reload_system);
    schedule.add(Stage::Input, "look switch", look_switch_system);
    schedule.add(Stage::Input, "camera feed", camera_feed_system);

    schedule.add(Stage::Simulate, "begin step", begin_step_system);
    schedule.add(Stage::Simulate, "drops", drop_system).run_if(wave_field_in_use());
    schedule.add(Stage::Simulate, "wave", wave_system).run_if(wave_field_in_use());

    schedule.add(Stage::Render, "surface", surface_system).run_if(wave_field_in_use()).run_if(output_on());
    schedule.add(Stage::Render, "camera environment", camera_environment_system).run_if(output_on());
    schedule.add(Stage::Render, "analytic ripples", analytic_ripple_system)
        .run_if(drops_are(DropModel::analytic))
        .run_if(output_on());
    schedule.add(Stage::Render, "grid drops", grid_drop_system)
        .run_if(drops_are(DropModel::grid))
        .run_if(output_on());
    schedule.add(Stage::Render, "puddle", puddle_system).run_if(look_is(Scene::puddle)).run_if(output_on());
    schedule.add(Stage::Render, "ocean", ocean_system).run_if(look_is(Scene::ocean)).run_if(output_on());
    schedule.add(Stage::Render, "street", street_system).run_if(look_is(Scene::street)).run_if(output_on());
    schedule.add(Stage::Render, "rain overlay", rain_overlay_system)
        .run_if(rain_overlay_on())
        .run_if(output_on());
    return {};
}

}  // namespace puddle::systems
