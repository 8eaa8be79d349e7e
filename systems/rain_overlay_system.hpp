#pragma once
// Rain streaks (REFERENCE.md section 3's four parallax layers) blended over whatever scene was drawn,
// when overlay.rain = true. Runs after the scene passes, before present.

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/frame_clock.hpp"
#include "systems/lazy_pipeline.hpp"
#include "systems/render_system.hpp"

namespace puddle::systems {

// Resource.
struct RainOverlay {
    LazyPipeline pass;
};

Result<void> prepare_rain_overlay(gpu::Device& device, RainOverlay& rain);

void rain_overlay_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                         RainOverlay& rain, const RenderTarget& target);

}  // namespace puddle::systems
