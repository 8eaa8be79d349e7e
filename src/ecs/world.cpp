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

bool World::alive(Entity e) const {
    return e.index < generations_.size() && alive_[e.index] && generations_[e.index] == e.generation;
}

}  // namespace puddle::ecs
