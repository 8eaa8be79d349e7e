// Tests for src/ecs/world.hpp: entities and generations, sparse-set component storage, resources.
#include "ecs/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace puddle::ecs {
namespace {

struct Position {
    float x = 0, y = 0;
};
struct Velocity {
    int v = 0;
};
struct Name {
    std::string text;
};

std::set<std::uint32_t> indices_of(const std::vector<Entity>& entities) {
    std::set<std::uint32_t> out;
    for (Entity e : entities) out.insert(e.index);
    return out;
}

TEST(World, SpawnGivesDistinctLiveEntities) {
    World world;
    EXPECT_EQ(world.entity_count(), 0u);
    const Entity a = world.spawn();
    const Entity b = world.spawn();
    EXPECT_TRUE(a.valid());
    EXPECT_TRUE(b.valid());
    EXPECT_NE(a, b);
    EXPECT_EQ(a.index, 0u);
    EXPECT_EQ(b.index, 1u);
    EXPECT_EQ(a.generation, 0u);
    EXPECT_TRUE(world.alive(a));
    EXPECT_TRUE(world.alive(b));
    EXPECT_EQ(world.entity_count(), 2u);
}

TEST(World, DespawnKillsOnlyThatEntity) {
    World world;
    const Entity a = world.spawn();
    const Entity b = world.spawn();
    world.despawn(a);
    EXPECT_FALSE(world.alive(a));
    EXPECT_TRUE(world.alive(b));
    EXPECT_EQ(world.entity_count(), 1u);
    world.despawn(a);  // twice is a no-op, the count must not drop again
    EXPECT_EQ(world.entity_count(), 1u);
    EXPECT_TRUE(world.alive(b));
}

TEST(World, DefaultEntityIsInvalidAndNotAlive) {
    World world;
    const Entity none{};
    EXPECT_FALSE(none.valid());
    EXPECT_FALSE(world.alive(none));
    EXPECT_EQ(world.get<Position>(none), nullptr);
}

TEST(World, RespawnReusesTheSlotWithANewGeneration) {
    World world;
    const Entity old = world.spawn();
    world.add(old, Position{1, 2});
    world.despawn(old);
    const Entity fresh = world.spawn();
    EXPECT_EQ(fresh.index, old.index);
    EXPECT_EQ(fresh.generation, old.generation + 1);
    EXPECT_NE(fresh, old);
    EXPECT_TRUE(world.alive(fresh));
    EXPECT_FALSE(world.alive(old));
    // Despawn removed the component: the new occupant of the slot starts empty.
    EXPECT_EQ(world.get<Position>(fresh), nullptr);
    EXPECT_EQ(world.get<Position>(old), nullptr);
}

TEST(World, StaleHandleDoesNotSeeTheNewOccupantsComponents) {
    World world;
    const Entity old = world.spawn();
    world.despawn(old);
    const Entity fresh = world.spawn();
    ASSERT_EQ(fresh.index, old.index);
    world.add(fresh, Position{7, 8});
    EXPECT_EQ(world.get<Position>(old), nullptr);
    ASSERT_NE(world.get<Position>(fresh), nullptr);
    EXPECT_EQ(world.get<Position>(fresh)->x, 7.0f);
    world.remove<Position>(old);  // removing through a stale handle must not touch the new entity
    ASSERT_NE(world.get<Position>(fresh), nullptr);
    EXPECT_EQ(world.get<Position>(fresh)->y, 8.0f);
    world.despawn(old);  // nor may despawning it
    EXPECT_TRUE(world.alive(fresh));
    EXPECT_EQ(world.entity_count(), 1u);
}

TEST(World, AddGetRemoveComponents) {
    World world;
    const Entity e = world.spawn();
    EXPECT_EQ(world.get<Position>(e), nullptr);
    Position& p = world.add(e, Position{1, 2});
    EXPECT_EQ(p.x, 1.0f);
    EXPECT_EQ(p.y, 2.0f);
    EXPECT_EQ(world.get<Position>(e), &p);
    world.add(e, Velocity{5});
    ASSERT_NE(world.get<Velocity>(e), nullptr);
    EXPECT_EQ(world.get<Velocity>(e)->v, 5);

    // Writing through get<> changes the stored value.
    world.get<Position>(e)->x = 3;
    EXPECT_EQ(world.get<Position>(e)->x, 3.0f);

    // Adding the same type again replaces the value, it does not add a second one.
    world.add(e, Position{9, 9});
    EXPECT_EQ(world.get<Position>(e)->x, 9.0f);
    EXPECT_EQ(world.storage<Position>().size(), 1u);

    world.remove<Position>(e);
    EXPECT_EQ(world.get<Position>(e), nullptr);
    ASSERT_NE(world.get<Velocity>(e), nullptr);
    EXPECT_EQ(world.get<Velocity>(e)->v, 5);
    world.remove<Position>(e);  // removing what is not there is a no-op
    EXPECT_EQ(world.storage<Position>().size(), 0u);
    EXPECT_TRUE(world.alive(e));
}

TEST(World, EachVisitsExactlyTheHolders) {
    World world;
    std::vector<Entity> all;
    for (int i = 0; i < 6; ++i) all.push_back(world.spawn());
    for (int i : {0, 2, 5}) world.add(all[static_cast<std::size_t>(i)], Position{static_cast<float>(i), 0});
    world.add(all[1], Velocity{1});

    std::vector<Entity> visited;
    float sum = 0;
    world.each<Position>([&](Entity e, Position& p) {
        visited.push_back(e);
        sum += p.x;
        EXPECT_EQ(world.get<Position>(e), &p);
    });
    EXPECT_EQ(visited.size(), 3u);
    EXPECT_EQ(indices_of(visited), (std::set<std::uint32_t>{all[0].index, all[2].index, all[5].index}));
    EXPECT_EQ(sum, 7.0f);

    std::vector<Entity> with_velocity;
    world.each<Velocity>([&](Entity e, Velocity&) { with_velocity.push_back(e); });
    ASSERT_EQ(with_velocity.size(), 1u);
    EXPECT_EQ(with_velocity[0], all[1]);

    int calls = 0;
    world.each<Name>([&](Entity, Name&) { ++calls; });
    EXPECT_EQ(calls, 0);
}

TEST(World, EachCanModifyComponents) {
    World world;
    const Entity a = world.spawn();
    const Entity b = world.spawn();
    world.add(a, Velocity{1});
    world.add(b, Velocity{10});
    world.each<Velocity>([](Entity, Velocity& v) { v.v *= 2; });
    EXPECT_EQ(world.get<Velocity>(a)->v, 2);
    EXPECT_EQ(world.get<Velocity>(b)->v, 20);
}

TEST(World, SwapRemoveKeepsTheOtherComponentsIntact) {
    World world;
    std::vector<Entity> e;
    for (int i = 0; i < 4; ++i) {
        e.push_back(world.spawn());
        world.add(e.back(), Name{"n" + std::to_string(i)});
        world.add(e.back(), Velocity{i * 10});
    }
    // Removing the first moves the last into its dense slot; every other entity keeps its own value.
    world.remove<Name>(e[0]);
    EXPECT_EQ(world.get<Name>(e[0]), nullptr);
    ASSERT_NE(world.get<Name>(e[1]), nullptr);
    ASSERT_NE(world.get<Name>(e[2]), nullptr);
    ASSERT_NE(world.get<Name>(e[3]), nullptr);
    EXPECT_EQ(world.get<Name>(e[1])->text, "n1");
    EXPECT_EQ(world.get<Name>(e[2])->text, "n2");
    EXPECT_EQ(world.get<Name>(e[3])->text, "n3");
    // The other storage is untouched, including for the entity whose Name was removed.
    for (int i = 0; i < 4; ++i) EXPECT_EQ(world.get<Velocity>(e[static_cast<std::size_t>(i)])->v, i * 10);

    // Despawning from the middle does the same across every storage.
    world.despawn(e[2]);
    EXPECT_EQ(world.get<Name>(e[2]), nullptr);
    EXPECT_EQ(world.get<Velocity>(e[2]), nullptr);
    EXPECT_EQ(world.get<Name>(e[1])->text, "n1");
    EXPECT_EQ(world.get<Name>(e[3])->text, "n3");
    EXPECT_EQ(world.get<Velocity>(e[0])->v, 0);
    EXPECT_EQ(world.get<Velocity>(e[1])->v, 10);
    EXPECT_EQ(world.get<Velocity>(e[3])->v, 30);
    EXPECT_EQ(world.storage<Name>().size(), 2u);
    EXPECT_EQ(world.storage<Velocity>().size(), 3u);

    // Removing the last dense element (no swap) also leaves the rest alone.
    world.remove<Velocity>(e[3]);
    EXPECT_EQ(world.get<Velocity>(e[0])->v, 0);
    EXPECT_EQ(world.get<Velocity>(e[1])->v, 10);
    EXPECT_EQ(world.get<Name>(e[3])->text, "n3");

    std::vector<Entity> names;
    world.each<Name>([&](Entity x, Name&) { names.push_back(x); });
    EXPECT_EQ(indices_of(names), (std::set<std::uint32_t>{e[1].index, e[3].index}));
}

TEST(World, ReservedStorageIsReusedWhenRespawningManyTimes) {
    constexpr std::size_t n = 64;
    World world;
    world.storage<Position>().reserve(n);
    std::vector<Entity> live;
    for (std::size_t i = 0; i < n; ++i) {
        live.push_back(world.spawn());
        world.add(live.back(), Position{static_cast<float>(i), 0});
    }
    const Position* const dense = world.storage<Position>().components().data();
    const Entity* const owners = world.storage<Position>().entities().data();

    for (int round = 0; round < 1000; ++round) {
        // Replace a rotating subset, as the drop system does every cycle.
        for (std::size_t k = 0; k < 8; ++k) {
            Entity& e = live[(static_cast<std::size_t>(round) * 8 + k) % n];
            world.despawn(e);
            e = world.spawn();
            world.add(e, Position{static_cast<float>(round), 1});
        }
        ASSERT_EQ(world.storage<Position>().components().data(), dense) << "reallocated in round " << round;
        ASSERT_EQ(world.storage<Position>().entities().data(), owners) << "reallocated in round " << round;
    }
    EXPECT_EQ(world.entity_count(), n);
    EXPECT_EQ(world.storage<Position>().size(), n);
    // Slots were recycled through the free list: no index beyond the first n was ever handed out.
    for (Entity e : live) {
        EXPECT_LT(e.index, n);
        EXPECT_TRUE(world.alive(e));
        EXPECT_NE(world.get<Position>(e), nullptr);
    }
}

struct Counter {
    int value = 0;
};
struct Label {
    explicit Label(std::string t, int n) : text(std::move(t) + std::to_string(n)) {}
    std::string text;
};

TEST(World, Resources) {
    World world;
    EXPECT_EQ(world.try_resource<Counter>(), nullptr);

    Counter& c = world.insert_resource<Counter>(Counter{3});
    EXPECT_EQ(c.value, 3);
    EXPECT_EQ(&world.resource<Counter>(), &c);
    EXPECT_EQ(world.try_resource<Counter>(), &c);
    world.resource<Counter>().value = 4;
    EXPECT_EQ(world.try_resource<Counter>()->value, 4);

    // Constructor arguments are forwarded.
    Label& l = world.insert_resource<Label>("frame", 7);
    EXPECT_EQ(l.text, "frame7");
    EXPECT_EQ(world.resource<Label>().text, "frame7");

    // Inserting again replaces the value.
    world.insert_resource<Counter>(Counter{10});
    EXPECT_EQ(world.resource<Counter>().value, 10);

    world.remove_resource<Counter>();
    EXPECT_EQ(world.try_resource<Counter>(), nullptr);
    ASSERT_NE(world.try_resource<Label>(), nullptr);  // the other resource stays
    EXPECT_EQ(world.resource<Label>().text, "frame7");
    world.remove_resource<Counter>();  // removing a missing resource is a no-op
    EXPECT_EQ(world.try_resource<Counter>(), nullptr);
}

// Records its destruction in a shared log: the order resources die in.
struct Noted {
    Noted(std::vector<std::string>* destroyed_log, std::string noted_name)
        : log(destroyed_log), name(std::move(noted_name)) {}
    Noted(const Noted&) = delete;
    ~Noted() { log->push_back(name); }
    std::vector<std::string>* log;
    std::string name;
};
struct Screen : Noted {
    using Noted::Noted;
};
struct Gpu : Noted {
    using Noted::Noted;
};
struct Field : Noted {
    using Noted::Noted;
};

TEST(World, ResourcesDieInReverseOrderOfInsertion) {
    // The display's EGL context must outlive every GPU object made with it, whatever the hash order.
    std::vector<std::string> log;
    {
        World world;
        world.insert_resource<Screen>(&log, "screen");
        world.insert_resource<Gpu>(&log, "gpu");
        world.insert_resource<Field>(&log, "field");
    }
    EXPECT_EQ(log, (std::vector<std::string>{"field", "gpu", "screen"}));
}

TEST(World, AReplacedResourceKeepsItsPlaceInTheOrder) {
    std::vector<std::string> log;
    {
        World world;
        world.insert_resource<Screen>(&log, "screen");
        world.insert_resource<Gpu>(&log, "gpu 1");
        world.insert_resource<Field>(&log, "field");
        world.insert_resource<Gpu>(&log, "gpu 2");  // "gpu 1" dies now
        EXPECT_EQ(log, (std::vector<std::string>{"gpu 1"}));
        EXPECT_EQ(world.resource<Gpu>().name, "gpu 2");
        world.remove_resource<Field>();
    }
    EXPECT_EQ(log, (std::vector<std::string>{"gpu 1", "field", "gpu 2", "screen"}));
}

struct Backend {
    virtual ~Backend() = default;
    virtual int kind() const = 0;
};
struct HeadlessBackend final : Backend {
    explicit HeadlessBackend(int* destroyed_count) : destroyed(destroyed_count) {}
    ~HeadlessBackend() override { ++*destroyed; }
    int kind() const override { return 7; }
    int* destroyed;
};

TEST(World, AnAdoptedImplementationIsFoundByItsInterface) {
    int destroyed = 0;
    {
        World world;
        Backend& b = world.adopt_resource<Backend>(std::make_unique<HeadlessBackend>(&destroyed));
        EXPECT_EQ(&world.resource<Backend>(), &b);
        EXPECT_EQ(world.resource<Backend>().kind(), 7);
        EXPECT_EQ(destroyed, 0);
    }
    EXPECT_EQ(destroyed, 1);
}

}  // namespace
}  // namespace puddle::ecs
