// The control for the two checks beside it: the same reads, with the right types, compile. Built by
// ctest with -fsyntax-only (tests/CMakeLists.txt), so a broken include path cannot pass as a refusal.
#include "params/param_store.hpp"

using puddle::params::ParamId;

int main() {
    const puddle::params::Params p;
    const int drops = p.get<ParamId::rain_drop_count>();
    const float speed = p.get<ParamId::rain_speed>();
    const puddle::params::SceneKind scene = p.get<ParamId::scene_kind>();
    return drops + static_cast<int>(speed) + (scene == puddle::params::SceneKind::ocean ? 1 : 0);
}
