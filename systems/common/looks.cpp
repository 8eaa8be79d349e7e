#include "systems/common/looks.hpp"

namespace puddle::systems {

const LookEntry* Looks::find(const ShownLook& look) const {
    for (const LookEntry& entry : entries)
        if (entry.matches(look)) return &entry;
    return nullptr;
}

bool Looks::takes_rain_overlay(const ShownLook& look) const {
    const LookEntry* entry = find(look);
    return !entry || entry->takes_rain_overlay;
}

Result<void> prepare_chosen_look(gpu::Device& device, const Looks& looks, const ShownLook& chosen) {
    const LookEntry* entry = looks.find(chosen);
    return entry ? entry->prepare(device) : Result<void>{};
}

}  // namespace puddle::systems
