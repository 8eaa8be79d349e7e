#pragma once
// The Engine wires one display backend, the GPU device, the World and the Schedule together and runs
// frames. The puddle binary, the benchmark and the GPU tests all drive the same Engine.

#include <functional>
#include <memory>
#include <vector>

#include "assets/image.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "platform/display.hpp"
#include "util/result.hpp"

namespace puddle::app {

class Engine {
public:
    // Makes the display (exit code 4 on failure), the device, loads assets (3) and builds the systems.
    // `input_plugin` adds systems that run first in the input stage (live tuning), before the puddle's.
    using Plugin = std::function<void(ecs::World&, ecs::Schedule&)>;
    static Result<std::unique_ptr<Engine>> create(const params::Params& params,
                                                  const platform::DisplayOptions& display_options,
                                                  const gpu::DeviceOptions& device_options = {},
                                                  const Plugin& input_plugin = {});
    ~Engine();

    // Runs one frame that advances simulated time by dt seconds: input, the due simulation steps,
    // render, present. An error means the display failed (a lost GPU or screen).
    Result<void> frame(double dt);
    // The last rendered frame, top row first. Call before present() has shown it where that matters
    // (window, kms): the engine does so when `capture_next_frame()` was called.
    void capture_next_frame() { capture_ = true; }
    const assets::Image& captured() const { return captured_; }
    // Hands the captured frame over (8 MB at 1080p) rather than copying it.
    assets::Image take_captured() { return std::move(captured_); }
    // Reads the frame target now (headless: always valid after a frame).
    assets::Image read_frame();

    ecs::World& world() { return world_; }
    params::Params& params();
    gpu::Device& device();
    platform::Display& display() { return *display_; }

private:
    Engine() = default;
    std::unique_ptr<platform::Display> display_;
    ecs::World world_;
    ecs::Schedule schedule_;
    Result<void> present_result_;
    bool capture_ = false;
    assets::Image captured_;
};

}  // namespace puddle::app
