#pragma once
// The adaptive render scale (render.target_fps, render.min_scale): the frame loop's side of
// systems/output/scale_controller.hpp. Each frame is timed on the GPU where timer queries exist
// (gpu/gpu_timer.hpp) and by the wall clock between frames; the controller's scale reaches the output
// canvas (systems/output/output_canvas.hpp) on the next frame. Registered by systems::add_display_plugin:
//   input:   gpu timer begin   starts timing this frame on the GPU
//   present: adaptive scale    ends it, feeds the controller, logs one line when the scale settles
// Off (render.target_fps 0, or -1 on a display without a refresh: headless) the scale is render.scale
// and nothing is timed, so fixed-step headless runs repeat exactly.

#include <optional>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/output/scale_controller.hpp"
#include "util/monotonic_clock.hpp"

namespace puddle::systems {

// Resource.
struct AdaptiveScale {
    float scale = 1;                // the render scale in effect: render.scale, or below it while adaptive
    double target_fps = 0;          // render.target_fps resolved; 0: off
    double display_refresh_hz = 0;  // the display's refresh, for target_fps -1; 0: none (headless)
    ScaleTuning timing;             // hold_s, steps and margins; target and scales come from the parameters
    std::optional<ScaleController> controller;  // while on
    gpu::GpuTimer timer;                        // made the first time it is on
    bool timer_made = false;
    double last_frame_s = -1;  // the clock at the previous frame's end; -1: none yet
    // The last window ran at render.min_scale and missed the target (the --stats line says so); said
    // once per controller, with the figures and the settings that would hold it.
    bool short_at_floor = false;
    bool short_at_floor_said = false;
    double (*clock)() = monotonic_seconds;  // tests may step their own
};

// render.target_fps as frames per second: -1 is the display's refresh (0 without one), 0 is off.
double resolved_target_fps(const params::Params& params, double display_refresh_hz);

// Input stage: starts timing the frame's GPU work (nothing while off or without timer queries).
void gpu_timer_begin_system(AdaptiveScale& adaptive);
// Present stage, before the present: ends the GPU timing, feeds this frame to the controller and sets
// the next frame's scale; (re)starts or stops the controller when the parameters change. One info line
// when the scale settles: "render: adaptive scale settled at 0.70 (p90 GPU time 14.1 ms; target 60 fps)";
// one warning, once per setting of the parameters, when even render.min_scale misses the target, with the
// frame rate this GPU holds there and the render.min_scale that would hold the target.
void adaptive_scale_system(gpu::Device& device, const params::Params& params, AdaptiveScale& adaptive);

}  // namespace puddle::systems
