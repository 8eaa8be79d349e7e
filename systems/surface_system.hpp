#pragma once
// Once per displayed frame, after the simulation steps: turns the newest wave field into the surface
// texture the render pass samples (height and slopes, filterable: RGBA16F, or RGBA8 where half-float
// targets are missing).

#include <cstddef>

#include "gpu/device.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/wave_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// What selects the surface pass's shader: its output encoding and the field's.
struct SurfaceVariant {
    bool unorm = false;
    bool field_fixed_point = false;
};
constexpr std::size_t surface_variant_index(const SurfaceVariant& v) {
    return (v.unorm ? 2u : 0u) + (v.field_fixed_point ? 1u : 0u);
}
// One pipeline per variant, built on first use and kept through resolution changes.
using SurfacePipelines = render::PipelineCache<SurfaceVariant, 4, surface_variant_index>;

// Resource.
struct Surface {
    gpu::Texture texture;
    SurfacePipelines pipelines;
    gpu::Sampler field_sampler;  // nearest, for the field
    gpu::Sampler sampler;        // linear, clamp: how the render pass reads the surface
    int resolution = 0;
    bool unorm = false;  // RGBA8 fallback encoding (SURFACE_UNORM in the shaders)
    bool field_fixed_point = false;

    SurfaceVariant variant() const { return {unorm, field_fixed_point}; }
};

// Makes (or remakes) the surface texture for `field`'s size and encoding, keeping the pipelines. On an
// error `surface` is left as it was.
Result<void> build_surface(gpu::Device& device, const WaveField& field, Surface& surface);
void surface_system(gpu::Device& device, const WaveField& field, Surface& surface);

}  // namespace puddle::systems
