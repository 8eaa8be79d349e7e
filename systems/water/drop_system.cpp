#include "systems/water/drop_system.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::systems {

namespace {

// splitmix64's finaliser: a well-mixed 64-bit hash, identical on every platform.
std::uint64_t mix64(std::uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float unit_float(std::uint64_t h) {
    return static_cast<float>(h >> 40) / static_cast<float>(1ull << 24);
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

float drop_phase_offset(int slot) {
    return static_cast<float>(slot) * 0.3711f;
}

float drop_activation(double p) {
    return static_cast<float>(smoothstep(0.0, 0.15, p) * smoothstep(0.35, 0.2, p));
}

DropSample sample_drop(std::uint32_t seed, int slot, std::int64_t cycle, float intensity) {
    std::uint64_t h = mix64(seed);
    h = mix64(h ^ static_cast<std::uint64_t>(slot));
    h = mix64(h ^ static_cast<std::uint64_t>(cycle));
    const float x = unit_float(h), y = unit_float(mix64(h + 1)), r = unit_float(mix64(h + 2));
    return {{x, y}, intensity * (0.5f + 0.5f * r)};
}

void drop_system(const params::Params& params, const FrameClock& clock, ecs::World& world, DropSlots& slots,
                 LiveDrops& live) {
    using params::ParamId;
    // A capillary field's rain is hashed in its own shader (wave_step.frag): no cycling drops then.
    const bool capillary = params.get<ParamId::wave_model>() == params::WaveModel::capillary;
    const int count = capillary ? 0 : std::min(params.get<ParamId::rain_drop_count>(), max_drops);
    const double speed = params.get<ParamId::rain_speed>();
    const auto seed = static_cast<std::uint32_t>(params.get<ParamId::rain_seed>());
    const float intensity = params.get<ParamId::rain_intensity>();
    const float resolution = static_cast<float>(params.get<ParamId::wave_resolution>());
    const double scaled = clock.sim_time * speed;

    live.count = 0;
    for (int slot = 0; slot < max_drops; ++slot) {
        ecs::Entity& e = slots.entity[static_cast<std::size_t>(slot)];
        if (slot >= count) {  // fewer drops than before: retire the rest
            if (e.valid()) world.despawn(e), e = {};
            continue;
        }
        const double t = scaled + 0.7 * static_cast<double>(drop_phase_offset(slot));
        const auto cycle = static_cast<std::int64_t>(std::floor(t));
        Drop* drop = e.valid() ? world.get<Drop>(e) : nullptr;
        const DropSample s = sample_drop(seed, slot, cycle, intensity);
        if (!drop || drop->cycle != cycle) {  // a new cycle: the old drop retires, a new one falls elsewhere
            if (e.valid()) world.despawn(e);
            e = world.spawn();
            drop = &world.add(e, Drop{slot, cycle, s.position, s.strength});
        }
        // Sampled again every step, not kept from the cycle's start: a new seed or intensity applies at
        // once, as on a screen that starts now, so the drops are a function of seed, parameters and step.
        drop->position = s.position;
        drop->strength = s.strength;
        const float amount = drop->strength * drop_activation(t - static_cast<double>(cycle));
        if (amount > 0.01f)
            live.drops[static_cast<std::size_t>(live.count++)] =
                glm::vec4(drop->position * resolution, amount, 0.0f);
    }
}

}  // namespace puddle::systems
