#pragma once
// The puddle render pass: draws the scene for the camera into the frame target (REFERENCE.md §1).
// environment_override: a cube sampled in place of env.cube (the camera environment while it streams).

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/environment_system.hpp"
#include "systems/surface_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource: where this frame goes, set by the run loop from the display each frame.
struct RenderTarget {
    gpu::FrameTarget target;
};

// Resource: one pipeline per render.method.
struct PuddleRenderer {
    gpu::Pipeline intersect;
    gpu::Pipeline raymarch;
};

Result<void> build_puddle_renderer(gpu::Device& device, const Surface& surface, PuddleRenderer& renderer);

void render_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const PuddleRenderer& renderer,
                   const RenderTarget& target, const gpu::Texture* environment_override = nullptr);

}  // namespace puddle::systems
