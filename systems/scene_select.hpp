#pragma once
// Which look the config chose (scene.kind and drops.model as enums), and which look is on screen: the
// same, except while a newly chosen look's pipelines are still being built (systems/look_switch.hpp).

#include <string>

#include "params/param_store.hpp"

namespace puddle::systems {

enum class Scene { Puddle, Ocean, Street };
enum class DropModel { Pulse, Analytic, Grid };

Scene selected_scene(const params::Params& params);
DropModel selected_drop_model(const params::Params& params);

// Resource: the look the render systems draw (their run conditions read it).
struct ShownLook {
    Scene scene = Scene::Puddle;
    DropModel drops = DropModel::Pulse;  // used while the scene is the puddle
    bool operator==(const ShownLook&) const = default;
};

ShownLook selected_look(const params::Params& params);

// "ocean", "puddle with analytic drops": for log lines.
std::string describe(const ShownLook& look);

}  // namespace puddle::systems
