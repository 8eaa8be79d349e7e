#include "systems/scene_select.hpp"

namespace puddle::systems {

using params::ParamId;

Scene selected_scene(const params::Params& params) {
    const std::string& s = params.s(ParamId::scene_kind);
    if (s == "ocean") return Scene::Ocean;
    if (s == "street") return Scene::Street;
    return Scene::Puddle;
}

DropModel selected_drop_model(const params::Params& params) {
    const std::string& s = params.s(ParamId::drops_model);
    if (s == "analytic") return DropModel::Analytic;
    if (s == "grid") return DropModel::Grid;
    return DropModel::Pulse;
}

}  // namespace puddle::systems

namespace puddle::systems {

ShownLook selected_look(const params::Params& params) {
    return {.scene = selected_scene(params), .drops = selected_drop_model(params)};
}

std::string describe(const ShownLook& look) {
    switch (look.scene) {
        case Scene::Ocean:
            return "ocean";
        case Scene::Street:
            return "street";
        case Scene::Puddle:
            break;
    }
    switch (look.drops) {
        case DropModel::Analytic:
            return "puddle with analytic drops";
        case DropModel::Grid:
            return "puddle with grid drops";
        case DropModel::Pulse:
            break;
    }
    return "puddle with pulse drops";
}

}  // namespace puddle::systems
