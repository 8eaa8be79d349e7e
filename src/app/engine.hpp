#pragma once
// The Engine wires one display backend, the GPU device, the World and the Schedule together and runs
// frames. The puddle binary, the benchmark and the GPU tests all drive the same Engine, each installing
// the features it wants as plugins (the puddle's is systems::add_puddle_plugin).

#include <functional>
#include <memory>
#include <vector>

#include "assets/image.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "platform/display.hpp"
#include "systems/display/display_plugin.hpp"
#include "util/result.hpp"

namespace puddle::app {

class Engine {
public:
    // A feature: inserts its resources and registers its systems (Bevy's Plugin::build). Run once, in
    // create(), in the order given; inside a stage, systems run in the order they were registered.
    using Plugin = std::function<Result<void>(ecs::World&, ecs::Schedule&)>;

    // Makes the display (exit code 4 on failure) and the device, installs the display plugin
    // (systems/display/display_plugin.hpp: the frame's start, the output canvas, capture and present), then
    // each of `plugins` in order (their errors, such as an asset that does not load (3), are returned as they
    // are). The schedule is logged at debug level, one line per system.
    static Result<std::unique_ptr<Engine>> create(const params::Params& params,
                                                  const platform::DisplayOptions& display_options,
                                                  const gpu::DeviceOptions& device_options,
                                                  const std::vector<Plugin>& plugins);
    ~Engine();

    // Runs one frame that advances time by dt seconds: one run of the schedule (input, the due
    // simulation steps, render, present). An error means the display failed (a lost GPU or screen).
    Result<void> frame(double dt);
    // One stage alone, outside a frame (the benchmark times the simulate stage).
    void run_stage(ecs::Stage stage) { schedule_.run_stage(stage, world_); }
    // Runs the exit stage (saves state, tells systemd it is stopping), once; later calls do nothing.
    void shutdown();

    // The next frame is read back before it is presented (a window or KMS may not keep it).
    void capture_next_frame() { world_.resource<systems::FrameCapture>().requested = true; }
    const assets::Image& captured() { return world_.resource<systems::FrameCapture>().image; }
    // Hands the captured frame over (8 MB at 1080p) rather than copying it.
    assets::Image take_captured() { return std::move(world_.resource<systems::FrameCapture>().image); }
    // Reads the frame target now (headless: always valid after a frame).
    assets::Image read_frame();

    // Makes this engine's GL context current on the calling thread: call before using device() outside
    // a frame when another engine may have made its own current (frames make theirs current themselves).
    void make_current() { display().make_current(); }

    ecs::World& world() { return world_; }
    const ecs::Schedule& schedule() const { return schedule_; }
    params::Params& params() { return world_.resource<params::Params>(); }
    gpu::Device& device() { return world_.resource<gpu::Device>(); }
    platform::Display& display() { return world_.resource<platform::Display>(); }

private:
    Engine() = default;
    ecs::World world_;  // the display first: it outlives every GPU object (resources die newest first)
    ecs::Schedule schedule_;
    bool shut_down_ = false;
};

}  // namespace puddle::app
