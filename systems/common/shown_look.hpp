#pragma once
// Which look the config chose (scene.kind and drops.model as enums), and which look is on screen: the
// same, except while a newly chosen look's pipelines are still being built (systems/common/look_switch.hpp).

#include <string>

#include "ecs/schedule.hpp"
#include "params/param_store.hpp"

namespace puddle::systems {

using Scene = params::SceneKind;       // scene.kind: puddle, ocean, street
using DropModel = params::DropsModel;  // drops.model: pulse, analytic, grid

Scene selected_scene(const params::Params& params);
DropModel selected_drop_model(const params::Params& params);

// Resource: the look the render systems draw (their run conditions read it).
struct ShownLook {
    Scene scene = Scene::puddle;
    DropModel drops = DropModel::pulse;  // used while the scene is the puddle
    bool operator==(const ShownLook&) const = default;
};

ShownLook selected_look(const params::Params& params);

// "ocean", "puddle with analytic drops": for log lines.
std::string describe(const ShownLook& look);

// Run conditions on the look on screen (ShownLook), for the systems that draw or simulate one look.
ecs::RunCondition look_is(Scene scene);        // "look is ocean"
ecs::RunCondition drops_are(DropModel drops);  // the puddle with these drops: "drops are grid"
// The puddle's surface comes from the simulated wave field only with the pulse drops; analytic and grid
// drops write it themselves, and the other scenes need no simulation.
ecs::RunCondition wave_field_in_use();
// overlay.rain is on and the look shown takes the streaks (Looks::takes_rain_overlay): "the rain overlay
// is on" (it draws over whichever look is shown, but the window).
ecs::RunCondition rain_overlay_on();

}  // namespace puddle::systems
