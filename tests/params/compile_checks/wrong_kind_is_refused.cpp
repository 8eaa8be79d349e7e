// Must NOT compile: scene.kind is a SceneKind, not a number (ctest expects the compiler to fail).
#include "params/param_store.hpp"

using puddle::params::ParamId;

int main() {
    const puddle::params::Params p;
    const int scene = p.get<ParamId::scene_kind>();
    return scene;
}
