#include "assets/cloud_layer.hpp"

#include <cmath>

#include "assets/procedural_shading.hpp"

namespace puddle::assets {
namespace {

using namespace shading;

// Value noise on a lattice of `period` cells per side that wraps, so the tile repeats seamlessly.
float periodic_noise(float x, float y, int period, std::uint32_t key) {
    const float fx = std::floor(x), fy = std::floor(y);
    const auto wrap = [period](int i) {
        return static_cast<std::uint32_t>(((i % period) + period) % period);
    };
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    const std::uint32_t x0 = wrap(ix), x1 = wrap(ix + 1), y0 = wrap(iy), y1 = wrap(iy + 1);
    const float a = unit(hash(x0, y0, key)), b = unit(hash(x1, y0, key));
    const float c = unit(hash(x0, y1, key)), d = unit(hash(x1, y1, key));
    return a + (b - a) * tx + (c - a) * ty + (a - b - c + d) * tx * ty;
}

}  // namespace

Image cloud_layer_image(std::uint64_t seed) {
    const std::uint32_t key = hash(static_cast<std::uint32_t>(seed), 0xc10dU);
    constexpr int n = cloud_layer_size;
    constexpr int base_cells = 8;  // one lattice cell per deck unit at the first octave (as the sky had)
    Image img = Image::make(n, n);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            float sum = 0.0f, amp = 0.5f;
            int cells = base_cells;
            for (int o = 0; o < 4; ++o) {
                // Each octave's lattice shifted by a hashed fraction, so their lattice lines do not align.
                const float shift = 0.37f + 0.5f * unit(hash(key, as_u32(o)));
                const float u = (static_cast<float>(x) + 0.5f) / n * static_cast<float>(cells) + shift;
                const float v = (static_cast<float>(y) + 0.5f) / n * static_cast<float>(cells) + shift;
                sum += amp * periodic_noise(u, v, cells, key + as_u32(o));
                amp *= 0.5f;
                cells *= 2;
            }
            const float coverage = smoothstep(0.45f, 0.75f, sum / 0.9375f);
            const auto byte = static_cast<std::uint8_t>(std::lround(coverage * 255.0f));
            std::uint8_t* p = img.pixel8(x, y);
            p[0] = p[1] = p[2] = byte;
            p[3] = 255;
        }
    }
    return img;
}

float cloud_coverage(const Image& layer, float u, float v) {
    const int n = layer.width;
    const float x = u * static_cast<float>(n) - 0.5f, y = v * static_cast<float>(layer.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const auto wrap = [](int i, int size) { return ((i % size) + size) % size; };
    const int x0 = wrap(static_cast<int>(fx), n), x1 = wrap(static_cast<int>(fx) + 1, n);
    const int y0 = wrap(static_cast<int>(fy), layer.height),
              y1 = wrap(static_cast<int>(fy) + 1, layer.height);
    const float tx = x - fx, ty = y - fy;
    const auto at = [&](int px, int py) { return static_cast<float>(layer.pixel8(px, py)[0]) / 255.0f; };
    const float top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * tx;
    const float bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * tx;
    return top + (bottom - top) * ty;
}

}  // namespace puddle::assets
