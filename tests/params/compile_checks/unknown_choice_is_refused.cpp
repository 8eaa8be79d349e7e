// Must NOT compile: "forest" is not one of scene.kind's choices (ctest expects the compiler to fail).
#include "params/param_store.hpp"

using puddle::params::ParamId;

int main() {
    const puddle::params::Params p;
    return p.get<ParamId::scene_kind>() == puddle::params::SceneKind::forest ? 1 : 0;
}
