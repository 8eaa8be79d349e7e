#include "systems/puddle/puddle_plugin.hpp"

#include <spdlog/spdlog.h>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/analytic_ripples/analytic_ripple_system.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/common/look_switch.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/output_power.hpp"
#include "systems/common/shown_look.hpp"
#include "systems/grid_drops/grid_drop_system.hpp"
#include "systems/ocean/ocean_system.hpp"
#include "systems/puddle/render_system.hpp"
#include "systems/rain_overlay/rain_overlay_system.hpp"
#include "systems/sky/camera_environment.hpp"
#include "systems/sky/camera_system.hpp"
#include "systems/sky/cloud_layer_system.hpp"
#include "systems/sky/environment_system.hpp"
#include "systems/street/street_system.hpp"
#include "systems/tuning/synced_changes.hpp"
#include "systems/water/capillary_step.hpp"
#include "systems/water/drop_system.hpp"
#include "systems/water/surface_system.hpp"
#include "systems/water/wave_system.hpp"
#include "systems/window/window_system.hpp"

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
    const bool want_fixed = wave_field_fixed_point(device, params);
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

}  // namespace

Result<void> add_puddle_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& device = world.resource<gpu::Device>();
    const Params& params = world.resource<Params>();

    auto& env = world.insert_resource<Environment>();
    if (auto r = load_environment(device, params, env); !r) return r;
    world.insert_resource<EnvironmentReload>();
    if (auto r = build_clouds(device, world.insert_resource<Clouds>()); !r) return r;
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
    world.insert_resource<Looks>();
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
    schedule.add(Stage::Render, "cloud drift", cloud_drift_system).run_if(output_on());
    // The looks, each with its entry in Looks: one line a look.
    add_analytic_ripples_plugin(world, schedule);
    add_grid_drops_plugin(world, schedule);
    schedule.add(Stage::Render, "puddle", puddle_system).run_if(look_is(Scene::puddle)).run_if(output_on());
    add_ocean_plugin(world, schedule);
    add_street_plugin(world, schedule);
    add_window_plugin(world, schedule);
    if (auto r = add_rain_overlay_plugin(world, schedule); !r) return r;
    // The pipelines of the look the config chose are built now, so a broken shader stops start-up with its
    // message; looks chosen later are built off the frame thread by the look switch.
    return prepare_chosen_look(device, world.resource<Looks>(), world.resource<ShownLook>());
}

}  // namespace puddle::systems
