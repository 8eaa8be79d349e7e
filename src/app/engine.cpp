#include "app/engine.hpp"

#include <spdlog/spdlog.h>

#include "ecs/frame_time.hpp"

namespace puddle::app {

Result<std::unique_ptr<Engine>> Engine::create(const params::Params& params,
                                               const platform::DisplayOptions& display_options,
                                               const gpu::DeviceOptions& device_options,
                                               const std::vector<Plugin>& plugins) {
    std::unique_ptr<Engine> engine(new Engine());
    ecs::World& world = engine->world_;
    auto made = platform::create_display(display_options);
    if (!made) return made.error();
    platform::Display& display = world.adopt_resource<platform::Display>(std::move(made).value());

    auto& device = world.insert_resource<gpu::Device>(device_options);
    spdlog::info("gpu: {}", device.caps().summary());
    if (auto r = display.prepare(device); !r) return r.error();
    if (device_options.background_compiles) {
        if (auto context = display.create_worker_context())
            device.start_background_compiles(std::move(context).value());
        else
            spdlog::warn("{}; looks chosen while running compile on the frame thread",
                         context.error().message);
    }
    world.insert_resource<params::Params>(params);
    if (auto r = systems::add_display_plugin(world, engine->schedule_); !r) return r.error();
    for (const Plugin& plugin : plugins)
        if (auto r = plugin(world, engine->schedule_); !r) return r.error();
    for (const std::string& line : engine->schedule_.describe()) spdlog::debug("schedule: {}", line);
    return engine;
}

// The world's resources die newest first: every GPU object before the device, the device before the
// display's EGL context.
Engine::~Engine() = default;

Result<void> Engine::frame(double dt) {
    world_.resource<ecs::FrameTime>().dt_seconds = dt;
    schedule_.run_frame(world_);
    return world_.resource<systems::PresentStatus>().result;
}

void Engine::shutdown() {
    if (std::exchange(shut_down_, true)) return;
    schedule_.run_exit(world_);
}

assets::Image Engine::read_frame() {
    return systems::read_display(display(), device());
}

}  // namespace puddle::app
