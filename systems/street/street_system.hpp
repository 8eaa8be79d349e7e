#pragma once
// The rainy-street scene at night (REFERENCE.md section 3), drawn when scene.kind = street: one fullscreen
// pass in screen space (street.frag): facades, lamps, wet ground and sky. Its rain streaks are the rain
// overlay (the puddle has them too).
//
// Time reaches the shader only through StreetTime, computed here in double (render/shader_phase.hpp),
// each term modulo the period it repeats at, so the street never jumps and its floats stay small:
// lightning's two sines modulo 2 pi; the clouds' and the ground's drift as whole noise lattice cells and
// a fraction, and the facades' and lamps' as whole units and a fraction; each ripple and splash source,
// which repeats at its own period (seeded between 2.5 and 4.5 s, and 1 and 2.5 s), as its repeat number
// and age, and what the shader draws of it now (its spot, radius and strength); and each lamp's
// distance, size and fade. What is the same for every pixel is worked out here once a frame.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
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

inline constexpr int street_max_sources = 32;  // street.ripples' and street.splashes' maximum
inline constexpr int street_cloud_octaves = 5;
inline constexpr int street_max_lamps = 16;  // street.lamps' maximum, street.frag's MAX_LAMPS

// One kind of repeating source (ripples, splashes): its hash salt and the range of its periods.
struct StreetSourceKind {
    std::uint32_t salt;
    double min_period, max_period;  // seconds
};
inline constexpr StreetSourceKind street_ripple_kind{101u, 2.5, 4.5};
inline constexpr StreetSourceKind street_splash_kind{211u, 1.0, 2.5};

// Everything street.frag needs of the time `seconds`.
struct StreetTime {
    glm::vec2 lightning_phase{};                            // radians
    std::array<float, street_cloud_octaves> cloud_shift{};  // fraction of a lattice cell, sideways
    std::array<int, street_cloud_octaves> cloud_cells{};    // whole cells: the bits of a uint
    glm::vec3 ground_shift{};  // toward the viewer: the puddle outline, puddle detail and asphalt noises
    std::array<int, 3> ground_cells{};
    float street_shift = 0;  // the facades' and lamps' drift toward the viewer: fraction of a unit
    int street_cells = 0;    // and whole units (the bits of a uint)
    // Per lamp of a row, nearest first: (z, 1 / z, (0.006 / z)^2, shown), street_lamp's.
    std::array<glm::vec4, street_max_lamps> lamps{};
    std::array<float, street_max_sources> ripple_age{}, splash_age{};      // seconds
    std::array<int, street_max_sources> ripple_repeat{}, splash_repeat{};  // the bits of a uint
    // What street.frag draws of each source now (street_sources): (where on the ground, x and z; its ring's
    // radius; its strength).
    std::array<glm::vec4, street_max_sources> ripples{}, splashes{};
};
// `aspect`: the whole view's width / height, which sets where a source's screen spot lies on the ground.
StreetTime street_time(const params::Params& params, double seconds, float aspect);

// Where source i of `kind` falls in its repeat `repeat`: a random screen spot below the horizon (x across
// the view, y up to 0.9 of the way to the horizon), seeded by (i, repeat), so it is always in view, as a
// point of the ground (street.frag's ground_of: ((x - 0.5) aspect / depth, 1 / depth) * 0.3, depth =
// (horizon - y) / horizon).
glm::vec2 street_source_spot(const StreetSourceKind& kind, int i, int repeat, float horizon, float aspect);

// Lamp i (0 nearest) of a row of `count`, one a unit, at drift `shift` (the fraction of a unit the street
// has moved toward the viewer): at z = i + 1 - shift units, it shows fully from z = 0.45 (where it leaves
// the view) out to count - 1.5, fading to nothing by 0.15 and by count, so that as the street drifts no
// lamp pops in or out. (z, 1 / z, the square of its glow's size 0.006 / z, shown).
glm::vec4 street_lamp(int i, int count, double shift);

// Resource.
struct StreetRenderer {
    FullscreenPass pass;
    StreetRenderer();
};

void street_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   StreetRenderer& street, const RenderTarget& target);

// The street's plugin: its resource, its entry in Looks (scene.kind = street) and its render system.
void add_street_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
