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
