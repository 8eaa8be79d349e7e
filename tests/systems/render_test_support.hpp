#pragma once
// Rendering a small picture with chosen parameters, for the render tests and the golden images.

#include <initializer_list>
#include <string>

#include "params/config_loader.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {

inline constexpr glm::ivec2 render_test_size{160, 90};

// `frames` frames at 60 fps with the given --set values; small field for speed.
inline assets::Image render_with(std::initializer_list<std::string> sets, int frames = 45,
                                 glm::ivec2 size = render_test_size) {
    params::Params p =
        make_params({"wave.resolution=256", "wave.size=0.8", "rain.seed=11"});  // 3.1 mm texels
    apply_sets(p, sets);
    auto engine = make_engine(p, size);
    if (!engine) return {};
    return render_frames(*engine, frames);
}

// Mean over rows [y0, y1) of each row's luma standard deviation: the sky is smooth along a row, the
// ground (puddles) and the sea (waves) are not.
inline double row_contrast(const assets::Image& img, int y0, int y1) {
    double sum = 0;
    for (int y = y0; y < y1; ++y) sum += luma_stddev(img, 0, y, img.width, y + 1);
    return sum / (y1 - y0);
}

// The first row from the top whose contrast along it passes `threshold`: where the smooth sky ends.
inline int first_rough_row(const assets::Image& img, double threshold) {
    for (int y = 0; y < img.height; ++y)
        if (luma_stddev(img, 0, y, img.width, y + 1) > threshold) return y;
    return img.height;
}

}  // namespace puddle::test
