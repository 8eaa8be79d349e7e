#include "ecs/world.hpp"

namespace puddle::ecs {

Entity World::spawn() {
    std::uint32_t index;
    if (!free_list_.empty()) {
        index = free_list_.back();
        free_list_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(generations_.size());
        generations_.push_back(0);
        alive_.push_back(false);
    }
    alive_[index] = true;
    ++alive_count_;
    return Entity{index, generations_[index]};
}

void World::despawn(Entity e) {
    if (!alive(e)) return;
    for (auto& [type, storage] : storages_) storage->remove(e);
    alive_[e.index] = false;
    ++generations_[e.index];  // stale handles to this slot stop matching
    free_list_.push_back(e.index);
    --alive_count_;
}

World::~World() {
    index_.clear();
    while (!resources_.empty()) resources_.pop_back();  // newest first
}

void World::place(std::type_index type, std::unique_ptr<ResourceBase> holder) {
    auto [it, inserted] = index_.try_emplace(type, holder.get());
    if (inserted) {
        resources_.push_back(std::move(holder));
        return;
    }
    for (auto& slot : resources_)
        if (slot.get() == it->second) {
            slot = std::move(holder);  // the old value dies here; the new one takes its place in the order
            it->second = slot.get();
            return;
        }
}

void World::erase(std::type_index type) {
    auto it = index_.find(type);
    if (it == index_.end()) return;
    std::erase_if(resources_, [p = it->second](const auto& slot) { return slot.get() == p; });
    index_.erase(it);
}

bool World::alive(Entity e) const {
    return e.index < generations_.size() && alive_[e.index] && generations_[e.index] == e.generation;
}

}  // namespace puddle::ecs
