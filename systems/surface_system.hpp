#pragma once
// Once per displayed frame, after the simulation steps: turns the newest wave field into the surface
// texture the render pass samples (height and slopes, filterable: RGBA16F, or RGBA8 where half-float
// targets are missing).

#include "gpu/device.hpp"
#include "systems/wave_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct Surface {
    gpu::Texture texture;
    gpu::Pipeline pipeline;
    gpu::Sampler field_sampler;  // nearest, for the field
    gpu::Sampler sampler;        // linear, clamp: how the render pass reads the surface
    int resolution = 0;
    bool unorm = false;  // RGBA8 fallback encoding (SURFACE_UNORM in the shaders)
    bool field_fixed_point = false;
};

Result<void> build_surface(gpu::Device& device, const WaveField& field, Surface& surface);
void surface_system(gpu::Device& device, const WaveField& field, Surface& surface);

}  // namespace puddle::systems
