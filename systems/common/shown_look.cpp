#include "systems/common/shown_look.hpp"

#include "systems/common/looks.hpp"

namespace puddle::systems {

using params::ParamId;

Scene selected_scene(const params::Params& params) {
    return params.get<ParamId::scene_kind>();
}

DropModel selected_drop_model(const params::Params& params) {
    return params.get<ParamId::drops_model>();
}

}  // namespace puddle::systems

namespace puddle::systems {

ShownLook selected_look(const params::Params& params) {
    return {.scene = selected_scene(params), .drops = selected_drop_model(params)};
}

std::string describe(const ShownLook& look) {
    // Another scene by its scene.kind choice, so a new look needs no line here.
    if (look.scene != Scene::puddle) return std::string(params::choice_name(look.scene));
    return "puddle with " + std::string(params::choice_name(look.drops)) + " drops";
}

}  // namespace puddle::systems

namespace puddle::systems {

ecs::RunCondition look_is(Scene scene) {
    return {"look is " + std::string(params::choice_name(scene)),
            [scene](ecs::World& w) { return w.resource<ShownLook>().scene == scene; }};
}

ecs::RunCondition drops_are(DropModel drops) {
    return {"drops are " + std::string(params::choice_name(drops)), [drops](ecs::World& w) {
                const ShownLook& look = w.resource<ShownLook>();
                return look.scene == Scene::puddle && look.drops == drops;
            }};
}

ecs::RunCondition wave_field_in_use() {
    ecs::RunCondition pulse = drops_are(DropModel::pulse);
    pulse.name = "the wave field is in use";
    return pulse;
}

ecs::RunCondition rain_overlay_on() {
    return {"the rain overlay is on", [](ecs::World& w) {
                if (!w.resource<params::Params>().get<params::ParamId::overlay_rain>()) return false;
                const Looks* looks = w.try_resource<Looks>();
                return !looks || looks->takes_rain_overlay(w.resource<ShownLook>());
            }};
}

}  // namespace puddle::systems
