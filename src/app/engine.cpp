#include "app/engine.hpp"

#include <spdlog/spdlog.h>

#include "systems/frame_clock.hpp"
#include "systems/output_canvas.hpp"
#include "systems/puddle_plugin.hpp"
#include "systems/render_system.hpp"

namespace puddle::app {

Result<std::unique_ptr<Engine>> Engine::create(const params::Params& params,
                                               const platform::DisplayOptions& display_options,
                                               const gpu::DeviceOptions& device_options,
                                               const Plugin& input_plugin) {
    std::unique_ptr<Engine> engine(new Engine());
    auto display = platform::create_display(display_options);
    if (!display) return display.error();
    engine->display_ = std::move(display).value();

    auto& device = engine->world_.insert_resource<gpu::Device>(device_options);
    spdlog::info("gpu: {}", device.caps().summary());
    if (auto r = engine->display_->prepare(device); !r) return r.error();
    if (device_options.background_compiles) {
        if (auto context = engine->display_->create_worker_context())
            device.start_background_compiles(std::move(context).value());
        else
            spdlog::warn("{}; looks chosen while running compile on the frame thread", context.error().message);
    }
    engine->world_.insert_resource<params::Params>(params);
    engine->world_.insert_resource<systems::RenderTarget>();
    if (input_plugin) input_plugin(engine->world_, engine->schedule_);
    if (auto r = systems::add_puddle_plugin(engine->world_, engine->schedule_); !r) return r.error();

    Engine* self = engine.get();
    engine->world_.insert_resource<systems::OutputCanvas>();
    engine->schedule_.add_system(ecs::Stage::Present, "output canvas", [](ecs::World& w) {
        systems::output_canvas_system(w.resource<gpu::Device>(), w.resource<systems::OutputCanvas>());
    });
    engine->schedule_.add_system(ecs::Stage::Present, "capture", [self](ecs::World&) {
        if (!self->capture_) return;
        self->capture_ = false;
        self->captured_ = self->read_frame();
    });
    engine->schedule_.add_system(ecs::Stage::Present, "present",
                                 [self](ecs::World&) { self->present_result_ = self->display_->present(); });
    return engine;
}

// Members die in reverse order: the world (and every GPU object in it) before the display's EGL context.
Engine::~Engine() = default;

params::Params& Engine::params() { return world_.resource<params::Params>(); }
gpu::Device& Engine::device() {
    display_->make_current();  // callers go on to make GL calls through the device
    return world_.resource<gpu::Device>();
}

Result<void> Engine::frame(double dt) {
    display_->make_current();
    world_.resource<systems::FrameClock>().frame_dt = dt;
    world_.resource<systems::RenderTarget>().target =
        systems::begin_canvas_frame(world_.resource<gpu::Device>(), world_.resource<params::Params>(),
                                    world_.resource<systems::OutputCanvas>(), display_->frame_target());
    schedule_.run_frame(world_);
    return present_result_;
}

assets::Image Engine::read_frame() {
    display_->make_current();
    const gpu::FrameTarget target = display_->frame_target();
    assets::Image image = assets::Image::make(target.size.x, target.size.y);
    device().read_pixels(target, image.data);
    return image;
}

}  // namespace puddle::app
