#include "assets/procedural_ground.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::assets {

namespace {

std::uint64_t hash(std::uint64_t x) {
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdull;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ull;
    return x ^ (x >> 33);
}
float unit(std::uint64_t h) {
    return static_cast<float>(h >> 40) / static_cast<float>(1u << 24);
}

}  // namespace

Image cobblestone_ground(int size, std::uint64_t seed) {
    constexpr int cells = 8;  // cobbles per tile edge; the tile wraps, so cells wrap too
    Image img = Image::make(size, size);
    auto cell_point = [&](int cx, int cy) {
        const int wx = (cx + cells) % cells, wy = (cy + cells) % cells;
        const std::uint64_t h = hash(seed * 1315423911ull + static_cast<std::uint64_t>(wy * cells + wx));
        return std::pair{static_cast<float>(cx) + 0.2f + 0.6f * unit(h),
                         static_cast<float>(cy) + 0.2f + 0.6f * unit(hash(h))};
    };
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(size) * cells;
            const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(size) * cells;
            const int cx = static_cast<int>(std::floor(u)), cy = static_cast<int>(std::floor(v));
            float d1 = 1e9f, d2 = 1e9f;
            int best = 0;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    auto [px, py] = cell_point(cx + i, cy + j);
                    const float d = std::hypot(u - px, v - py);
                    if (d < d1)
                        d2 = d1, d1 = d, best = ((cy + j + cells) % cells) * cells + (cx + i + cells) % cells;
                    else if (d < d2)
                        d2 = d;
                }
            // Distance to the border between the two nearest cells: small in the joints.
            const float edge = std::clamp((d2 - d1) * 4.0f, 0.0f, 1.0f);
            const float shade = 0.75f + 0.25f * unit(hash(static_cast<std::uint64_t>(best) + seed));
            const float grain = 0.9f + 0.1f * unit(hash(static_cast<std::uint64_t>(y * size + x) ^ seed));
            const float stone = std::sqrt(edge) * shade * grain;
            std::uint8_t* p = img.pixel8(x, y);
            p[0] = static_cast<std::uint8_t>(std::clamp(40.0f + 120.0f * stone, 0.0f, 255.0f));
            p[1] = static_cast<std::uint8_t>(std::clamp(36.0f + 110.0f * stone, 0.0f, 255.0f));
            p[2] = static_cast<std::uint8_t>(std::clamp(32.0f + 100.0f * stone, 0.0f, 255.0f));
            p[3] = 255;
        }
    }
    return img;
}

}  // namespace puddle::assets
