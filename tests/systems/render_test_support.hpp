#pragma once
// Rendering a small picture with chosen parameters, for the render tests and the golden images.

#include <initializer_list>
#include <string>

#include "params/config_loader.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::test {

inline constexpr glm::ivec2 render_test_size{160, 90};

// `frames` frames at 60 fps with the given --set values; small field for speed.
inline assets::Image render_with(std::initializer_list<std::string> sets, int frames = 45,
                                 glm::ivec2 size = render_test_size) {
    params::Params p = make_params({"wave.resolution=256", "rain.seed=11"});
    apply_sets(p, sets);
    auto engine = make_engine(p, size);
    if (!engine) return {};
    return render_frames(*engine, frames);
}

}  // namespace puddle::test
