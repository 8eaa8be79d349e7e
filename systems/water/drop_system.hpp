#pragma once
// Drops of the reference's wave model (REFERENCE.md §1; wave.model = capillary has none: its rain falls in
// the wave shader): drop i cycles once per unit of time scaled by rain.speed, at phase offset
// i * 0.3711; each cycle it lands at a new pseudo-random spot with a new strength, and its activation is a
// bell over the cycle. Positions come from a seeded integer hash on the CPU, so every GPU shows the same
// rain for a seed. Drops are entities; the live ones are packed for the wave pass.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "ecs/world.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"

namespace puddle::systems {

inline constexpr int max_drops = 128;  // the wave shader's uniform array size (MAX_DROPS)

// Component of a drop entity.
struct Drop {
    int slot = 0;            // which of the rain.drop_count drops
    std::int64_t cycle = 0;  // which of its cycles this is
    glm::vec2 position{};    // in the height field, 0..1 on both axes
    float strength = 0.0f;   // intensity * (0.5 + 0.5 * random)
};

// Resource: the entity of each slot (invalid when the slot is empty).
struct DropSlots {
    std::array<ecs::Entity, max_drops> entity{};
};

// Resource, rewritten every step: drops whose strength * activation exceeds 0.01, as
// (x texels, y texels, strength * activation, 0) for the wave pass.
struct LiveDrops {
    int count = 0;
    std::array<glm::vec4, max_drops> drops{};
};

// The pure part, for tests and the system: where and how strong drop `slot` is in `cycle`.
struct DropSample {
    glm::vec2 position;
    float strength;
};
DropSample sample_drop(std::uint32_t seed, int slot, std::int64_t cycle, float intensity);
float drop_phase_offset(int slot);    // slot * 0.3711
float drop_activation(double phase);  // smoothstep(0, .15, p) * smoothstep(.35, .2, p)

void drop_system(const params::Params& params, const FrameClock& clock, ecs::World& world, DropSlots& slots,
                 LiveDrops& live);

}  // namespace puddle::systems
