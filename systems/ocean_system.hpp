#pragma once
// The open-water scene (REFERENCE.md section 2), drawn when scene.kind = ocean: one fullscreen pass
// that marches the choppy fBm height field (ocean.frag). Needs no simulation: the sea is a function of time.

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/frame_clock.hpp"
#include "systems/lazy_pipeline.hpp"
#include "systems/render_system.hpp"

namespace puddle::systems {

// Resource.
struct OceanRenderer {
    LazyPipeline pass;
};

// Builds the pipeline now (start-up, when the config chose the ocean); otherwise the system does on first
// use.
Result<void> prepare_ocean(gpu::Device& device, OceanRenderer& ocean);

void ocean_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                  OceanRenderer& ocean, const RenderTarget& target);

}  // namespace puddle::systems
