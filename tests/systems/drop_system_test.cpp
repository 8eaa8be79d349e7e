// Tests for systems/water/drop_system.hpp: seeded, reproducible drops; their strength and activation; the
// live-drop list; and that drop entities are recycled, never accumulated.
#include "systems/water/drop_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/common.hpp>
#include <set>
#include <utility>
#include <vector>

namespace puddle::systems {
namespace {

using params::ParamId;
using params::ParamSource;

// One drop as seen after a step, by slot.
struct Seen {
    int slot;
    std::int64_t cycle;
    glm::vec2 position;
    float strength;
    friend bool operator==(const Seen&, const Seen&) = default;
};

// The drop system with everything it reads and writes, stepped as the simulate stage would.
struct Rain {
    // The cycling drops are the reference wave model's (a capillary field's rain falls in its shader).
    explicit Rain(int seed = 1) {
        params.set(ParamId::rain_seed, seed, ParamSource::CommandLine);
        params.set<ParamId::wave_model>(params::WaveModel::reference, ParamSource::CommandLine);
    }

    void step() {
        begin_step_system(clock);
        drop_system(params, clock, world, slots, live);
    }
    std::vector<Seen> drops() {
        std::vector<Seen> out;
        world.each<Drop>([&](ecs::Entity, Drop& d) {
            out.push_back({d.slot, d.cycle, d.position, d.strength});
        });
        std::sort(out.begin(), out.end(), [](const Seen& a, const Seen& b) { return a.slot < b.slot; });
        return out;
    }

    params::Params params;
    FrameClock clock;  // 1/60 s steps
    ecs::World world;
    DropSlots slots;
    LiveDrops live;
};

std::vector<std::vector<Seen>> run(int seed, int steps) {
    Rain rain(seed);
    std::vector<std::vector<Seen>> history;
    for (int i = 0; i < steps; ++i) {
        rain.step();
        history.push_back(rain.drops());
    }
    return history;
}

TEST(DropSystem, SameSeedGivesIdenticalRain) {
    const auto a = run(1, 600);
    const auto b = run(1, 600);
    const auto count =
        static_cast<std::size_t>(std::get<int>(params::decl(ParamId::rain_drop_count).default_value));
    ASSERT_EQ(a.size(), 600u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].size(), count) << "step " << i;
        ASSERT_EQ(a[i], b[i]) << "step " << i;
    }
    // Over 10 s at 1 cycle/s every drop fell several times, so positions really were resampled.
    std::set<std::int64_t> cycles;
    for (const auto& step : a) cycles.insert(step[0].cycle);
    EXPECT_GE(cycles.size(), 10u);
}

TEST(DropSystem, DifferentSeedGivesDifferentRain) {
    const auto a = run(1, 600);
    const auto b = run(2, 600);
    int differing_steps = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i].size(), b[i].size());
        for (std::size_t k = 0; k < a[i].size(); ++k)
            if (a[i][k].position != b[i][k].position) {
                ++differing_steps;
                break;
            }
    }
    EXPECT_EQ(differing_steps, 600);
}

TEST(DropSystem, SampleDropIsAPureFunction) {
    const DropSample a = sample_drop(7, 3, 42, 0.6f);
    const DropSample b = sample_drop(7, 3, 42, 0.6f);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.strength, b.strength);
    EXPECT_NE(sample_drop(7, 3, 43, 0.6f).position, a.position);  // next cycle
    EXPECT_NE(sample_drop(7, 4, 42, 0.6f).position, a.position);  // next slot
    EXPECT_NE(sample_drop(8, 3, 42, 0.6f).position, a.position);  // next seed
    // Intensity scales the strength only.
    const DropSample twice = sample_drop(7, 3, 42, 1.2f);
    EXPECT_EQ(twice.position, a.position);
    EXPECT_FLOAT_EQ(twice.strength, 2.0f * a.strength);
}

TEST(DropSystem, StrengthIsHalfToFullIntensityAndPositionsCoverTheField) {
    for (float intensity : {0.6f, 1.0f, 4.0f}) {
        float lo = intensity, hi = 0.0f;
        glm::vec2 min_pos(1.0f), max_pos(0.0f);
        for (std::uint32_t seed = 0; seed < 4; ++seed)
            for (int slot = 0; slot < max_drops; ++slot)
                for (std::int64_t cycle = -5; cycle < 20; ++cycle) {
                    const DropSample s = sample_drop(seed, slot, cycle, intensity);
                    ASSERT_GE(s.strength, 0.5f * intensity);
                    ASSERT_LE(s.strength, intensity);
                    ASSERT_GE(s.position.x, 0.0f);
                    ASSERT_LT(s.position.x, 1.0f);
                    ASSERT_GE(s.position.y, 0.0f);
                    ASSERT_LT(s.position.y, 1.0f);
                    lo = std::min(lo, s.strength), hi = std::max(hi, s.strength);
                    min_pos = glm::min(min_pos, s.position), max_pos = glm::max(max_pos, s.position);
                }
        // 12800 samples use the whole range, not a corner of it.
        EXPECT_LT(lo, 0.52f * intensity);
        EXPECT_GT(hi, 0.98f * intensity);
        EXPECT_LT(min_pos.x, 0.01f);
        EXPECT_LT(min_pos.y, 0.01f);
        EXPECT_GT(max_pos.x, 0.99f);
        EXPECT_GT(max_pos.y, 0.99f);
    }
}

TEST(DropSystem, DropEntitiesCarryStrengthWithinIntensity) {
    Rain rain;
    ASSERT_TRUE(rain.params.set(ParamId::rain_intensity, 2.0f, ParamSource::CommandLine));
    for (int i = 0; i < 300; ++i) {
        rain.step();
        for (const Seen& d : rain.drops()) {
            ASSERT_GE(d.strength, 1.0f);
            ASSERT_LE(d.strength, 2.0f);
        }
    }
}

TEST(DropActivation, ShapeOfTheBell) {
    EXPECT_EQ(drop_activation(0.0), 0.0f);
    EXPECT_EQ(drop_activation(-0.1), 0.0f);
    EXPECT_EQ(drop_activation(0.175), 1.0f);
    EXPECT_GT(drop_activation(0.05), 0.0f);
    EXPECT_LT(drop_activation(0.05), 1.0f);
    EXPECT_GT(drop_activation(0.3), 0.0f);
    EXPECT_LT(drop_activation(0.3), 1.0f);
    // Rises to the peak, then falls; nothing is above the peak value.
    const float peak = drop_activation(0.175);
    float previous = 0.0f;
    for (int i = 0; i <= 1000; ++i) {
        const double p = i / 1000.0;
        const float a = drop_activation(p);
        ASSERT_GE(a, 0.0f) << p;
        ASSERT_LE(a, peak) << p;
        if (p <= 0.175) {
            ASSERT_GE(a, previous) << p;
        } else {
            ASSERT_LE(a, previous) << p;
        }
        if (p >= 0.35) {
            ASSERT_EQ(a, 0.0f) << p;
        }
        previous = a;
    }
}

TEST(DropActivation, PhaseOffset) {
    EXPECT_EQ(drop_phase_offset(0), 0.0f);
    EXPECT_FLOAT_EQ(drop_phase_offset(1), 0.3711f);
    EXPECT_FLOAT_EQ(drop_phase_offset(10), 3.711f);
}

TEST(DropSystem, LiveDropsAreTheActiveOnesInTexels) {
    Rain rain;
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 40, ParamSource::CommandLine));
    const float resolution = static_cast<float>(rain.params.get<ParamId::wave_resolution>());
    int max_live = 0;
    for (int i = 0; i < 600; ++i) {
        rain.step();
        ASSERT_GE(rain.live.count, 0);
        ASSERT_LE(rain.live.count, 40) << "step " << i;
        for (int k = 0; k < rain.live.count; ++k) {
            const glm::vec4 d = rain.live.drops[static_cast<std::size_t>(k)];
            ASSERT_GT(d.z, 0.01f) << "step " << i;
            ASSERT_LE(d.z, rain.params.get<ParamId::rain_intensity>());
            ASSERT_GE(d.x, 0.0f);
            ASSERT_LT(d.x, resolution);
            ASSERT_GE(d.y, 0.0f);
            ASSERT_LT(d.y, resolution);
            ASSERT_EQ(d.w, 0.0f);
        }
        max_live = std::max(max_live, rain.live.count);
    }
    // A drop is active for about a third of its cycle, so some but not all are live at once.
    EXPECT_GT(max_live, 5);
    EXPECT_LT(max_live, 40);
}

TEST(DropSystem, LiveDropMatchesItsEntity) {
    Rain rain;
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 1, ParamSource::CommandLine));
    const float resolution = static_cast<float>(rain.params.get<ParamId::wave_resolution>());
    int live_steps = 0;
    for (int i = 0; i < 120; ++i) {
        rain.step();
        const std::vector<Seen> d = rain.drops();
        ASSERT_EQ(d.size(), 1u);
        const double phase = rain.clock.sim_time - static_cast<double>(d[0].cycle);  // slot 0, speed 1
        const float amount = d[0].strength * drop_activation(phase);
        if (amount > 0.01f) {
            ASSERT_EQ(rain.live.count, 1) << "step " << i;
            EXPECT_EQ(rain.live.drops[0], glm::vec4(d[0].position * resolution, amount, 0.0f));
            ++live_steps;
        } else {
            EXPECT_EQ(rain.live.count, 0) << "step " << i;
        }
    }
    EXPECT_GT(live_steps, 20);  // about 0.35 s of each 1 s cycle
    EXPECT_LT(live_steps, 60);
}

TEST(DropSystem, LoweringDropCountDespawnsTheExtraEntities) {
    Rain rain;
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 40, ParamSource::Config));
    rain.step();
    EXPECT_EQ(rain.world.entity_count(), 40u);
    EXPECT_EQ(rain.world.storage<Drop>().size(), 40u);

    std::vector<ecs::Entity> retired(rain.slots.entity.begin() + 5, rain.slots.entity.begin() + 40);
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 5, ParamSource::CommandLine));
    rain.step();
    EXPECT_EQ(rain.world.entity_count(), 5u);
    EXPECT_EQ(rain.world.storage<Drop>().size(), 5u);
    for (std::size_t s = 0; s < max_drops; ++s)
        EXPECT_EQ(rain.slots.entity[s].valid(), s < 5) << "slot " << s;
    for (ecs::Entity e : retired) EXPECT_FALSE(rain.world.alive(e));
    for (const Seen& d : rain.drops()) EXPECT_LT(d.slot, 5);
    EXPECT_LE(rain.live.count, 5);

    // Raising it again fills the slots back up.
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 12, ParamSource::CommandLine));
    rain.step();
    EXPECT_EQ(rain.world.entity_count(), 12u);
}

TEST(DropSystem, EntityCountNeverExceedsDropCountOverManyCycles) {
    Rain rain;
    ASSERT_TRUE(rain.params.set(ParamId::rain_drop_count, 16, ParamSource::CommandLine));
    ASSERT_TRUE(rain.params.set(ParamId::rain_speed, 10.0f, ParamSource::CommandLine));
    std::set<std::pair<std::uint32_t, std::uint32_t>> distinct;  // (index, generation)
    for (int i = 0; i < 3000; ++i) {  // 50 s at 10 cycles/s: about 500 cycles per drop
        rain.step();
        ASSERT_EQ(rain.world.entity_count(), 16u) << "step " << i;
        ASSERT_EQ(rain.world.storage<Drop>().size(), 16u) << "step " << i;
        for (std::size_t s = 0; s < 16; ++s)
            distinct.insert({rain.slots.entity[s].index, rain.slots.entity[s].generation});
    }
    // Every cycle made a new entity (so drops really were respawned), yet the slots were recycled.
    EXPECT_GT(distinct.size(), 16u * 400u);
    std::uint32_t max_index = 0;
    for (const auto& [index, generation] : distinct) max_index = std::max(max_index, index);
    EXPECT_LT(max_index, 16u);  // a despawned index is reused at once by the next spawn
}

// The simulation is a function of seed, parameters and step: a screen that has run since step 0
// and one that starts at step 100 see the same drops from there on, even when the seed and the intensity
// changed in the middle of the drops' cycles. Drops used to keep the place and strength their cycle began
// with, so the screen that ran through the change still had the old ones until each drop's next cycle.
TEST(DropSystem, DropsAreAFunctionOfSeedParametersAndStepAlone) {
    Rain ran_all_along(3);
    for (int i = 0; i < 100; ++i) ran_all_along.step();
    ASSERT_GT(ran_all_along.live.count, 0);
    ASSERT_TRUE(ran_all_along.params.set(ParamId::rain_seed, 9, ParamSource::CommandLine));
    ASSERT_TRUE(ran_all_along.params.set(ParamId::rain_intensity, 0.7f, ParamSource::CommandLine));
    Rain starts_now(9);
    ASSERT_TRUE(starts_now.params.set(ParamId::rain_intensity, 0.7f, ParamSource::CommandLine));
    starts_now.clock.step_index = ran_all_along.clock.step_index;
    for (int i = 0; i < 30; ++i) {
        ran_all_along.step();
        starts_now.step();
        ASSERT_EQ(ran_all_along.drops(), starts_now.drops()) << "step " << ran_all_along.clock.step_index;
        ASSERT_EQ(ran_all_along.live.count, starts_now.live.count);
        for (int d = 0; d < starts_now.live.count; ++d)
            ASSERT_EQ(ran_all_along.live.drops[static_cast<std::size_t>(d)],
                      starts_now.live.drops[static_cast<std::size_t>(d)]);
    }
}

// wave.model = capillary: its rain is hashed in the wave shader, so drop_system leaves no drops and no
// entities, whatever rain.drop_count says.
TEST(DropSystem, ACapillaryFieldHasNoCyclingDrops) {
    Rain rain;
    for (int i = 0; i < 30; ++i) rain.step();
    ASSERT_GT(rain.live.count, 0);
    ASSERT_TRUE(rain.params.set<ParamId::wave_model>(params::WaveModel::capillary, ParamSource::CommandLine));
    rain.step();
    EXPECT_EQ(rain.live.count, 0);
    EXPECT_TRUE(rain.drops().empty());
}

}  // namespace
}  // namespace puddle::systems
