#include "systems/scene_select.hpp"

#include <cmath>

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

float shader_time(double seconds) {
    return static_cast<float>(std::fmod(seconds, 4096.0));
}

}  // namespace puddle::systems
