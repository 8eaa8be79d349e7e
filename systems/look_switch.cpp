#include "systems/look_switch.hpp"

#include <spdlog/spdlog.h>

namespace puddle::systems {

void look_switch_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                        OceanRenderer& ocean, StreetRenderer& street, AnalyticRipples& ripples,
                        GridDrops& grid, ShownLook& shown) {
    const ShownLook wanted = selected_look(params);
    if (wanted == shown) return;
    bool ready = true;
    switch (wanted.scene) {
        case Scene::ocean:
            ready = request_ocean(device, ocean);
            break;
        case Scene::street:
            ready = request_street(device, street);
            break;
        case Scene::puddle:
            switch (wanted.drops) {
                case DropModel::analytic:
                    ready = request_analytic_ripples(device, surface, ripples);
                    break;
                case DropModel::grid:
                    ready = request_grid_drops(device, surface, grid);
                    break;
                case DropModel::pulse:
                    break;  // its passes are built with the wave field
            }
            break;
    }
    if (!ready) return;
    spdlog::debug("look: now showing {}", describe(wanted));
    shown = wanted;
}

}  // namespace puddle::systems
