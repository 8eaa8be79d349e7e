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

namespace puddle::systems {

namespace {
const char* scene_name(Scene scene) {
    switch (scene) {
        case Scene::Ocean: return "ocean";
        case Scene::Street: return "street";
        case Scene::Puddle: break;
    }
    return "puddle";
}
const char* drops_name(DropModel drops) {
    switch (drops) {
        case DropModel::Analytic: return "analytic";
        case DropModel::Grid: return "grid";
        case DropModel::Pulse: break;
    }
    return "pulse";
}
}  // namespace

ecs::RunCondition look_is(Scene scene) {
    return {std::string("look is ") + scene_name(scene),
            [scene](ecs::World& w) { return w.resource<ShownLook>().scene == scene; }};
}

ecs::RunCondition drops_are(DropModel drops) {
    return {std::string("drops are ") + drops_name(drops), [drops](ecs::World& w) {
                const ShownLook& look = w.resource<ShownLook>();
                return look.scene == Scene::Puddle && look.drops == drops;
            }};
}

ecs::RunCondition wave_field_in_use() {
    ecs::RunCondition pulse = drops_are(DropModel::Pulse);
    pulse.name = "the wave field is in use";
    return pulse;
}

}  // namespace puddle::systems
