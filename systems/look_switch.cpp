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
        case Scene::Ocean:
            ready = request_ocean(device, ocean);
            break;
        case Scene::Street:
            ready = request_street(device, street);
            break;
        case Scene::Puddle:
            switch (wanted.drops) {
                case DropModel::Analytic:
                    ready = request_analytic_ripples(device, surface, ripples);
                    break;
                case DropModel::Grid:
                    ready = request_grid_drops(device, surface, grid);
                    break;
                case DropModel::Pulse:
                    break;  // its passes are built with the wave field
            }
            break;
    }
    if (!ready) return;
    spdlog::debug("look: now showing {}", describe(wanted));
    shown = wanted;
}

}  // namespace puddle::systems
