#pragma once
// The open-water scene (REFERENCE.md section 2), drawn when scene.kind = ocean: a fullscreen pass that
// finds the choppy fBm height field along each view ray (ocean.frag), after, under ocean.method =
// height_map (the default), a pass that lays the height into this frame's map (ocean_height_map.hpp).
// Needs no simulation: the sea is a function of time.
//
// Time reaches the shader only as offsets computed here in double (render/shader_phase.hpp). Octave i
// (frequency f = 0.16 * 2^i cells per unit) has two terms travelling at t = ocean.speed * seconds and
// -0.8 t; each moves its noise and its sines by t * f. The noise's move is sent as whole lattice cells
// and a fraction, the sines' modulo pi (|sin| and |cos| repeat every pi): the sea never jumps, and its
// floats stay as small as at start-up, at any uptime.

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/fullscreen_pass.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/output_power.hpp"

namespace puddle::systems {

inline constexpr int ocean_max_octaves = 8;  // ocean.frag's MAX_OCTAVES, ocean.octaves' maximum

// What ocean.frag needs of the time `seconds`, per octave.
struct OceanTime {
    // (fraction of a noise cell, sine phase modulo pi) of the forward term, then of the backward term.
    std::array<glm::vec4, ocean_max_octaves> shift{};
    std::array<glm::ivec2, ocean_max_octaves> cells{};  // whole noise cells of each: the bits of a uint
};
OceanTime ocean_time(double seconds, double speed);

// Resource: the passes of each ocean.method. Start-up builds the height map's two (where the GPU renders
// half floats) and the secant search, the map's fallback: for an eye lower than the crests
// (ocean_height_map_min_eye), a GPU without half-float targets (EXT_color_buffer_half_float), or a map
// texture the driver refused. The reference's march is built when first asked for, and until it is ready
// the default is drawn.
struct OceanRenderer {
    FullscreenPass height;     // ocean_height.frag: the heights
    FullscreenPass slope;      // ocean_slope.frag: the map, with the slopes beside the heights
    FullscreenPass mapped;     // ocean.frag reading the map (OCEAN_HEIGHT_MAP)
    FullscreenPass secant;     // ocean.frag, OCEAN_SECANT
    FullscreenPass reference;  // ocean.frag, the reference's march
    // RGBA16F, remade when the layout's size changes: the heights (red), then the map (height, dh/dx, dh/dz).
    gpu::Texture heights, map;
    gpu::Sampler nearest;      // how the slope pass reads the heights
    gpu::Sampler map_sampler;  // bilinear, clamped: how ocean.frag reads the map
    bool map_refused = false;  // the driver refused the map's texture once: secant from then on
    OceanRenderer();
};

void ocean_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                  OceanRenderer& ocean, const RenderTarget& target);

// The ocean's plugin: its resource, its entry in Looks (scene.kind = ocean) and its render system.
void add_ocean_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
