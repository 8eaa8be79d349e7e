#pragma once
// The frame's start and end, as systems over the display (a World resource, platform::Display):
//   input:   begin frame   makes the display's context current and picks where the scene renders
//                          (the display, or the output canvas when it is turned or scaled) and which
//                          window of the whole view it shows (a video wall's tile, render/view_window.hpp)
//            gpu timer begin  starts timing the frame on the GPU while the adaptive scale is on
//   present: output canvas turns and scales the canvas onto the display
//            adaptive scale   ends the timing and sets the next frame's scale
//            (systems/output/adaptive_scale.hpp) capture       reads the frame back when asked (screenshots,
//            tests) present       shows it (swap, page flip, or the headless fence); nothing while the output
//            is off
// add_display_plugin registers them; the engine installs it before any feature, so the frame is one run
// of the schedule from the clock to the present.

#include "assets/image.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "platform/display.hpp"
#include "systems/common/output_power.hpp"
#include "systems/common/render_target.hpp"
#include "systems/output/adaptive_scale.hpp"
#include "systems/output/output_canvas.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource: a capture asked for (Engine::capture_next_frame) and the last image captured, top row first.
struct FrameCapture {
    bool requested = false;
    assets::Image image;
};

// Resource: what the last present returned; an error means a lost GPU or screen.
struct PresentStatus {
    Result<void> result;
};

void begin_frame_system(platform::Display& display, gpu::Device& device, const params::Params& params,
                        const AdaptiveScale& adaptive, OutputCanvas& canvas, RenderTarget& target);
void capture_system(platform::Display& display, gpu::Device& device, FrameCapture& capture);
// While the output is off nothing is presented (but the one black frame of going off), and the status
// stays good, so the watchdog is still pinged.
void present_system(platform::Display& display, OutputPower& power, PresentStatus& status);

// The display's frame target read back now, top row first (RGBA8, the display's size).
assets::Image read_display(platform::Display& display, gpu::Device& device);

// Needs platform::Display, gpu::Device and params::Params in the world; inserts RenderTarget,
// AdaptiveScale, OutputCanvas, OutputPower, ecs::FrameTime, FrameCapture and PresentStatus
// and registers the systems above.
Result<void> add_display_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
