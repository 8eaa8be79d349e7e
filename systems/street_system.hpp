#pragma once
// The rainy-street scene (REFERENCE.md section 3), drawn when scene.kind = street: one fullscreen pass in
// screen space (street.frag). Its rain streaks are the rain overlay, which any scene can have.

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/frame_clock.hpp"
#include "systems/lazy_pipeline.hpp"
#include "systems/render_system.hpp"

namespace puddle::systems {

// Resource.
struct StreetRenderer {
    LazyPipeline pass;
};

Result<void> prepare_street(gpu::Device& device, StreetRenderer& street);

void street_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   StreetRenderer& street, const RenderTarget& target);

}  // namespace puddle::systems
