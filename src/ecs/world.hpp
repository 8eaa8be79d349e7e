#pragma once
// The World: entities, one typed component storage per component type, and resources (singletons).
// Small on purpose: a signage display has tens of entities. Storage is a sparse set (dense arrays
// plus an index), so iteration is linear and add/remove are O(1); capacity, once reserved, is reused,
// so a steady-state frame that respawns entities does not allocate.

#include <cassert>
#include <cstdint>
#include <memory>
#include <span>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace puddle::ecs {

struct Entity {
    std::uint32_t index = UINT32_MAX;
    std::uint32_t generation = 0;
    friend bool operator==(Entity, Entity) = default;
    bool valid() const { return index != UINT32_MAX; }
};

class StorageBase {
public:
    virtual ~StorageBase() = default;
    virtual void remove(Entity e) = 0;
    virtual bool contains(Entity e) const = 0;
};

template <class C>
class Storage final : public StorageBase {
public:
    void reserve(std::size_t n) {
        dense_.reserve(n);
        owners_.reserve(n);
    }
    C& insert(Entity e, C value) {
        if (e.index >= sparse_.size()) sparse_.resize(e.index + 1, npos);
        if (sparse_[e.index] != npos) return dense_[sparse_[e.index]] = std::move(value);
        sparse_[e.index] = static_cast<std::uint32_t>(dense_.size());
        dense_.push_back(std::move(value));
        owners_.push_back(e);
        return dense_.back();
    }
    void remove(Entity e) override {
        if (!contains(e)) return;
        const std::uint32_t slot = sparse_[e.index];
        const std::uint32_t last = static_cast<std::uint32_t>(dense_.size() - 1);
        if (slot != last) {
            dense_[slot] = std::move(dense_[last]);
            owners_[slot] = owners_[last];
            sparse_[owners_[slot].index] = slot;
        }
        dense_.pop_back();
        owners_.pop_back();
        sparse_[e.index] = npos;
    }
    bool contains(Entity e) const override {
        return e.index < sparse_.size() && sparse_[e.index] != npos && owners_[sparse_[e.index]] == e;
    }
    C* find(Entity e) { return contains(e) ? &dense_[sparse_[e.index]] : nullptr; }
    const C* find(Entity e) const { return contains(e) ? &dense_[sparse_[e.index]] : nullptr; }
    std::size_t size() const { return dense_.size(); }
    std::span<C> components() { return dense_; }
    std::span<const Entity> entities() const { return owners_; }

private:
    static constexpr std::uint32_t npos = UINT32_MAX;
    std::vector<C> dense_;
    std::vector<Entity> owners_;
    std::vector<std::uint32_t> sparse_;
};

class World {
public:
    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    Entity spawn();
    void despawn(Entity e);
    bool alive(Entity e) const;
    std::size_t entity_count() const { return alive_count_; }

    template <class C>
    C& add(Entity e, C value) {
        assert(alive(e));
        return storage<C>().insert(e, std::move(value));
    }
    template <class C>
    C* get(Entity e) {
        return storage<C>().find(e);
    }
    template <class C>
    void remove(Entity e) {
        storage<C>().remove(e);
    }
    // Calls fn(Entity, C&) for every entity that has C. Do not add or remove C inside fn.
    template <class C, class Fn>
    void each(Fn&& fn) {
        Storage<C>& s = storage<C>();
        auto owners = s.entities();
        auto comps = s.components();
        for (std::size_t i = 0; i < comps.size(); ++i) fn(owners[i], comps[i]);
    }
    template <class C>
    Storage<C>& storage() {
        auto [it, inserted] = storages_.try_emplace(typeid(C));
        if (inserted) it->second = std::make_unique<Storage<C>>();
        return static_cast<Storage<C>&>(*it->second);
    }

    // Resources: one value per type, owned by the world (clock, params, GPU fields...). They are
    // destroyed in the reverse order of insertion, so a resource outlives every resource inserted after
    // it (the display's EGL context outlives the GPU objects made with it). Replacing a resource keeps
    // its place in that order.
    template <class R, class... Args>
    R& insert_resource(Args&&... args) {
        auto holder = std::make_unique<ResourceHolder<R>>(std::forward<Args>(args)...);
        R& ref = holder->value;
        place(typeid(R), std::move(holder));
        return ref;
    }
    // Takes an object made elsewhere (an implementation of an interface, such as the display backend).
    template <class R>
    R& adopt_resource(std::unique_ptr<R> value) {
        assert(value);
        auto holder = std::make_unique<AdoptedResource<R>>(std::move(value));
        R& ref = *holder->value;
        place(typeid(R), std::move(holder));
        return ref;
    }
    template <class R>
    R* try_resource() {
        auto it = index_.find(typeid(R));
        return it == index_.end() ? nullptr : static_cast<R*>(it->second->get());
    }
    template <class R>
    R& resource() {
        R* r = try_resource<R>();
        assert(r && "resource missing: register it in the feature's plugin");
        return *r;
    }
    template <class R>
    void remove_resource() {
        erase(typeid(R));
    }
    ~World();

private:
    struct ResourceBase {
        virtual ~ResourceBase() = default;
        virtual void* get() = 0;
    };
    template <class R>
    struct ResourceHolder final : ResourceBase {
        template <class... Args>
        explicit ResourceHolder(Args&&... args) : value(std::forward<Args>(args)...) {}
        void* get() override { return &value; }
        R value;
    };
    template <class R>
    struct AdoptedResource final : ResourceBase {
        explicit AdoptedResource(std::unique_ptr<R> v) : value(std::move(v)) {}
        void* get() override { return value.get(); }
        std::unique_ptr<R> value;
    };
    void place(std::type_index type, std::unique_ptr<ResourceBase> holder);
    void erase(std::type_index type);

    std::vector<std::uint32_t> generations_;
    std::vector<std::uint32_t> free_list_;
    std::vector<bool> alive_;
    std::size_t alive_count_ = 0;
    std::unordered_map<std::type_index, std::unique_ptr<StorageBase>> storages_;
    std::vector<std::unique_ptr<ResourceBase>> resources_;  // in insertion order
    std::unordered_map<std::type_index, ResourceBase*> index_;
};

}  // namespace puddle::ecs
