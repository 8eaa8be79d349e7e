#pragma once
// The rainy-street scene (REFERENCE.md section 3), drawn when scene.kind = street: one fullscreen pass in
// screen space (street.frag). Its rain streaks are the rain overlay, which any scene can have.
//
// Time reaches the shader only through StreetTime, computed here in double (render/shader_phase.hpp),
// each term modulo the period it repeats at, so the street never jumps and its floats stay small:
// lightning's two sines modulo 2 pi; the clouds' and the ground's drift as whole noise lattice cells and
// a fraction; and each ripple and splash source, which repeats at its own period (seeded between 2.5 and
// 4.5 s, and 1 and 2.5 s), as its repeat number and age.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

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
    std::array<float, street_max_sources> ripple_age{}, splash_age{};      // seconds
    std::array<int, street_max_sources> ripple_repeat{}, splash_repeat{};  // the bits of a uint
};
StreetTime street_time(const params::Params& params, double seconds);

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
