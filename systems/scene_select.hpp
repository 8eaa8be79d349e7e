#pragma once
// Which look the config chose: scene.kind and drops.model as enums, read every frame so a changed
// parameter switches the picture on the next frame (systems early-return when they are not chosen).

#include "params/param_store.hpp"

namespace puddle::systems {

enum class Scene { Puddle, Ocean, Street };
enum class DropModel { Pulse, Analytic, Grid };

Scene selected_scene(const params::Params& params);
DropModel selected_drop_model(const params::Params& params);

}  // namespace puddle::systems
