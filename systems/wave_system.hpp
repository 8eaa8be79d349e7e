#pragma once
// The wave field (REFERENCE.md §1): a discrete 2D wave equation with damping, one GPU pass per fixed
// step, ping-ponging between two textures holding (height, previous height). The field has its own
// resolution. Where the GPU cannot render to float textures, the field is fixed-point RG32I (heights
// times 65536), which every GLES 3.0 GPU can render to; a test checks both give the same field.

#include <array>
#include <cstdint>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/drop_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

inline constexpr float fixed_point_scale = 65536.0f;  // RG32I fallback: 1/65536 height units per step

// How the field's texels hold heights; each needs its own wave step (and surface) pipeline.
enum class FieldEncoding { float_rg32f, fixed_point_rg32i };
// The wave step's pipelines (render/pipeline_cache.hpp), one per encoding, each built the first time it is
// used and kept through resolution changes: a new wave.resolution compiles nothing.
using WaveStepPipelines = render::PipelineCache<FieldEncoding, 2, render::enum_index<FieldEncoding>>;

// Resource.
struct WaveField {
    std::array<gpu::Texture, 2> textures;
    int current = 0;  // index of the texture holding the newest step
    int resolution = 0;
    bool fixed_point = false;
    WaveStepPipelines step_pipelines;  // the step reads wave.damping
    gpu::Sampler nearest;
    gpu::Buffer drops;             // std140 vec4[max_drops]
    std::uint64_t generation = 0;  // the FrameClock::field_generation it was last cleared for
    // A field that could not be made: not retried every frame, only once the parameters change again.
    struct Request {
        int resolution = 0;
        bool fixed_point = false;
        bool operator==(const Request&) const = default;
    } requested;

    FieldEncoding encoding() const {
        return fixed_point ? FieldEncoding::fixed_point_rg32i : FieldEncoding::float_rg32f;
    }
    const gpu::Texture& newest() const { return textures[static_cast<std::size_t>(current)]; }
    // Height and previous height of every texel (fixed point converted back to height units), rows by z.
    std::vector<float> read_heights(gpu::Device& device) const;
};

// Makes (or remakes, when wave.resolution or wave.float_field changed) a flat field, keeping `field`'s
// step pipelines, sampler and drop buffer. On an error (a texture the GPU cannot make: exit code GpuMemory
// when it does not fit; a step shader that does not build) `field` is left as it was.
Result<void> build_wave_field(gpu::Device& device, const params::Params& params, WaveField& field);

// Simulate stage, once per fixed step: inject the live drops and advance the field one step. A new
// FrameClock::field_generation (a wall screen's warm-up) first makes the field flat and still.
void wave_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                 const LiveDrops& drops, WaveField& field);

}  // namespace puddle::systems
