#include "systems/common/look_switch.hpp"

#include <spdlog/spdlog.h>

namespace puddle::systems {

void look_switch_system(gpu::Device& device, const params::Params& params, const Looks& looks,
                        ShownLook& shown) {
    const ShownLook wanted = selected_look(params);
    if (wanted == shown) return;
    if (const LookEntry* entry = looks.find(wanted); entry && !entry->request(device)) return;
    spdlog::debug("look: now showing {}", describe(wanted));
    shown = wanted;
}

}  // namespace puddle::systems
