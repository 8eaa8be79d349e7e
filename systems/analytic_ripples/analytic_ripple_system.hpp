#pragma once
// Analytic ripples (REFERENCE.md section 4), the puddle's drops when drops.model = analytic: sources with
// birth time, position, amplitude, decays, angular frequency, speed and a maximum phase, packed into a
// small RGBA32F data texture each frame and summed in closed form into the puddle's surface texture
// (analytic_ripples.frag), so the puddle render is the same for every drop model.
//
// Source slot i of N is reborn every analytic.lifetime seconds, at times (k + i / N) * lifetime, at a
// spot and strength drawn from (rain.seed, i, k) like the pulse drops: always N live sources, the same on
// every screen. Ages are computed in double on the CPU, so float precision never depends on uptime.

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/output_power.hpp"
#include "systems/water/surface_system.hpp"

namespace puddle::systems {

inline constexpr int max_analytic_sources = 1024;  // rows of the data texture (analytic.sources' maximum)
inline constexpr int texels_per_source = 3;

// One source as the shader reads it (the row of the data texture).
struct AnalyticSource {
    glm::vec2 position{};                                              // texels
    float age = 0;                                                     // tau, seconds since birth
    float amplitude = 0;                                               // A
    float spatial_decay = 0, temporal_decay = 0, frequency_decay = 0;  // lambda1, lambda2, lambda3
    float angular_frequency = 0;                                       // Omega
    float speed = 0;                                                   // v, texels per second
    float max_phase = 0;                                               // radians
};

// Resource.
struct AnalyticRipples {
    render::SinglePipelineCache pass;
    gpu::Texture sources;  // RGBA32F, texels_per_source x max_analytic_sources
    gpu::Sampler nearest;
    std::vector<glm::vec4> texels =
        std::vector<glm::vec4>(std::size_t{texels_per_source} * max_analytic_sources);
    int count = 0;
};

// The pure part: source `slot` of `slots` at time `now` (its current life), for tests and the system.
AnalyticSource sample_analytic_source(const params::Params& params, int slot, int slots, double now,
                                      int field_resolution);
// Height of one source at distance d (texels): the closed form above, on the CPU (tests compare with it).
double analytic_height(const AnalyticSource& s, double d);

// Packs a source into its row of the data texture (before analytic_ripple_pass uploads it).
void set_analytic_source(AnalyticRipples& ripples, int index, const AnalyticSource& s);

Result<void> prepare_analytic_ripples(gpu::Device& device, const Surface& surface, AnalyticRipples& ripples);
// Starts building the pipeline off the frame thread (systems/common/look_switch.hpp) and, once it is built,
// makes the data texture; true once both are ready. A failure of either is logged once.
bool request_analytic_ripples(gpu::Device& device, const Surface& surface, AnalyticRipples& ripples);
// Uploads the first ripples.count sources and writes the surface from them (once the pipeline is built).
void analytic_ripple_pass(gpu::Device& device, AnalyticRipples& ripples, Surface& surface);

// Render stage, before the puddle pass, while the puddle with analytic drops is the look shown.
void analytic_ripple_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                            AnalyticRipples& ripples, Surface& surface);

// The analytic drops' plugin: their resource, their entry in Looks (the puddle with drops.model =
// analytic) and their render system. Needs the Surface and Looks resources.
void add_analytic_ripples_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
