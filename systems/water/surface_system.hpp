#pragma once
// Once per displayed frame, after the simulation steps: turns the newest wave field into the surface
// texture the render pass samples (height and slopes, filterable: RGBA16F, or RGBA8 where half-float
// targets are missing). The texture has a full mip chain: a capillary field repeats across the puddle
// and is read trilinear, so rings thinner than a pixel far away average out instead of shimmering.

#include <cstddef>

#include "gpu/device.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/water/wave_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// What selects the surface pass's shader: its output encoding and the field's.
struct SurfaceVariant {
    bool unorm = false;
    bool field_fixed_point = false;
    bool periodic = false;  // a capillary field: its differences wrap around the edges
};
constexpr std::size_t surface_variant_index(const SurfaceVariant& v) {
    return (v.periodic ? 4u : 0u) + (v.unorm ? 2u : 0u) + (v.field_fixed_point ? 1u : 0u);
}
// One pipeline per variant, built on first use and kept through resolution changes.
using SurfacePipelines = render::PipelineCache<SurfaceVariant, 8, surface_variant_index>;

// Resource.
struct Surface {
    gpu::Texture texture;
    SurfacePipelines pipelines;
    gpu::Sampler field_sampler;  // nearest, for the field
    gpu::Sampler sampler;        // linear, clamp: how the render pass reads a surface spanning the puddle
    gpu::Sampler tiled_sampler;  // trilinear, repeat: a capillary field repeating across the puddle
    // Bilinear, repeat, no mip levels or anisotropy: the same field read by the raymarch, whose loop
    // llvmpipe unrolls with each read's filtering inlined (an anisotropic read there took minutes to
    // compile).
    gpu::Sampler marched_sampler;
    int resolution = 0;
    bool unorm = false;  // RGBA8 fallback encoding (SURFACE_UNORM in the shaders)
    bool field_fixed_point = false;
    bool periodic = false;

    SurfaceVariant variant() const { return {unorm, field_fixed_point, periodic}; }
};

// Makes (or remakes) the surface texture for `field`'s size and encoding, keeping the pipelines. On an
// error `surface` is left as it was.
Result<void> build_surface(gpu::Device& device, const WaveField& field, Surface& surface);
// Renders level 0 and, for a capillary field, the mip chain below it.
void surface_system(gpu::Device& device, const WaveField& field, Surface& surface);

// Whether the render pass reads `surface` as a tile repeated across the puddle: a capillary field
// (wave.model) with pulse drops; otherwise it spans the puddle once, as the reference.
bool surface_tiled(const params::Params& params);

// The sampler the render pass reads `surface` with: for a tiled field repeating and trilinear (bilinear
// under render.method = raymarch), otherwise clamped and bilinear, as the reference.
const gpu::Sampler& surface_sampler(const params::Params& params, const Surface& surface);

}  // namespace puddle::systems
