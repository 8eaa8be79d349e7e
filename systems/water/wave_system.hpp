#pragma once
// The wave field: a height field driven by a wave equation on the GPU, ping-ponging between two textures
// holding (height, previous height), with its own resolution. wave.model picks the equation:
//   capillary: ripples of rain on shallow water in physical units (systems/water/capillary_step.hpp),
//              periodic, several passes per fixed step as stability needs, rain from rain.rate
//              (systems/water/rain_rate.hpp) hashed per cell of a rain grid into a small table before
//              each pass (shaders_gles/rain_cells.frag); heights in units of 0.1 mm.
//   reference: REFERENCE.md §1's damped wave equation, one pass per fixed step, the drops of drop_system.
//   Where the GPU cannot render to float textures, the field is fixed-point RG32I (heights
// times 65536), which every GLES 3.0 GPU can render to; a test checks both give the same field.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/water/drop_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

inline constexpr float fixed_point_scale = 65536.0f;  // RG32I fallback: 1/65536 height units per step

// How the field's texels hold heights; each needs its own wave step (and surface) pipeline.
enum class FieldEncoding { float_rg32f, fixed_point_rg32i };
// What selects the wave step's shader: the field's encoding and the equation.
struct WaveStepVariant {
    FieldEncoding encoding = FieldEncoding::float_rg32f;
    bool capillary = true;
    bool operator==(const WaveStepVariant&) const = default;
};
constexpr std::size_t wave_step_variant_index(const WaveStepVariant& v) {
    return 2u * static_cast<std::size_t>(v.encoding) + (v.capillary ? 1u : 0u);
}
// The wave step's pipelines (render/pipeline_cache.hpp), one per variant, each built the first time it is
// used and kept through resolution changes: a new wave.resolution compiles nothing.
using WaveStepPipelines = render::PipelineCache<WaveStepVariant, 4, wave_step_variant_index>;

// The rain's grid (rain_impacts.glsl): cells about this wide, each with at most one drop per slot, and at
// most this many a side (wave.size's 10 m at most makes 250).
inline constexpr double rain_cell_m = 0.04;
inline constexpr int rain_cells_max = 256;
inline constexpr double rain_slot_s = 0.25;  // RAIN_SLOT in the shader

// The hash rain_impacts.glsl starts each cell's from for rain slot `slot` (seconds / rain_slot_s, whole)
// under rain.seed `seed`: the same seed and time give the same drops on every screen, another seed others.
// The slot's count wraps at 2^32 (34 years of rain).
std::int32_t rain_slot_key(std::int64_t slot, std::int32_t seed);

// Resource.
struct WaveField {
    std::array<gpu::Texture, 2> textures;
    int current = 0;  // index of the texture holding the newest step
    int resolution = 0;
    bool fixed_point = false;
    bool capillary = true;             // wave.model when the field was made
    WaveStepPipelines step_pipelines;  // the step reads wave.damping
    gpu::Sampler nearest;
    gpu::Buffer drops;  // std140 vec4[max_drops]
    // capillary: the rain cells' table (rain_cells.frag), RGBA32I, 2 rain_cells_max a side, of which the
    // corner of 2 cells a side is drawn; made with the field, kept through resolution changes.
    gpu::Texture rain_cells;
    render::SinglePipelineCache rain_cells_pipeline;
    std::uint64_t generation = 0;  // the FrameClock::field_generation it was last cleared for
    // The rain's hashing uniforms (rain_impacts.glsl) of the last pass, capillary only: the surface pass
    // draws the splashes of the same drops from the rain cells' table. rain.z = 0: no rain (the table was
    // not drawn). splash: how bright a splash is, 1 at the default rain.intensity (0.3) and above, 0 with
    // no impulse or no rain.
    struct Rain {
        glm::vec4 rain{0.0f};
        glm::ivec2 slot_keys{0};  // rain_slot_key of the slot and the one before
        float slot_time = 0.0f;
        float texel_mm = 1.0f;
        float splash = 0.0f;
    } last_rain;
    // A field that could not be made: not retried every frame, only once the parameters change again.
    struct Request {
        int resolution = 0;
        bool fixed_point = false;
        bool capillary = true;
        bool operator==(const Request&) const = default;
    } requested;

    FieldEncoding encoding() const {
        return fixed_point ? FieldEncoding::fixed_point_rg32i : FieldEncoding::float_rg32f;
    }
    WaveStepVariant variant() const { return {encoding(), capillary}; }
    const gpu::Texture& newest() const { return textures[static_cast<std::size_t>(current)]; }
    // Height and previous height of every texel (fixed point converted back to height units), rows by z.
    std::vector<float> read_heights(gpu::Device& device) const;
};

// Whether the field is kept in fixed point (RG32I): when wave.float_field is off, or the GPU cannot render
// to float textures.
bool wave_field_fixed_point(const gpu::Device& device, const params::Params& params);

// Makes (or remakes, when wave.resolution, wave.float_field or wave.model changed) a flat field, keeping
// `field`'s step pipelines, sampler and drop buffer. On an error (a texture the GPU cannot make: exit code
// GpuMemory when it does not fit; a step shader that does not build) `field` is left as it was.
Result<void> build_wave_field(gpu::Device& device, const params::Params& params, WaveField& field);

// Simulate stage, once per fixed step: advance the field by the step, with the live drops (reference:
// drop_system's; capillary: explicit impacts, (x, y) in texels, diameter in mm, seconds since the impact
// at the end of this step, beside the rain the shader hashes). A new FrameClock::field_generation (a wall
// screen's warm-up) first makes the field flat and still.
void wave_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                 const LiveDrops& drops, WaveField& field);

}  // namespace puddle::systems
