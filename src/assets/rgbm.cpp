#include "assets/rgbm.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::assets {

std::array<std::uint8_t, 4> encode_rgbm(const float* rgb) {
    // The smallest 8-bit scale that holds the brightest channel: the most precision for the colour.
    const float brightest = std::max({rgb[0], rgb[1], rgb[2], 0.0f}) / rgbm_range;
    const float m = std::clamp(std::ceil(brightest * 255.0f), 1.0f, 255.0f) / 255.0f;
    auto unorm = [](float v) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const float scale = 1.0f / (m * rgbm_range);
    return {unorm(rgb[0] * scale), unorm(rgb[1] * scale), unorm(rgb[2] * scale), unorm(m)};
}

std::array<float, 3> decode_rgbm(const std::uint8_t* rgbm) {
    const float scale = rgbm[3] / 255.0f * rgbm_range / 255.0f;
    return {rgbm[0] * scale, rgbm[1] * scale, rgbm[2] * scale};
}

Image encode_rgbm(const Image& linear) {
    Image out = Image::make(linear.width, linear.height, PixelFormat::RGBA8);
    for (int y = 0; y < linear.height; ++y)
        for (int x = 0; x < linear.width; ++x) {
            const auto t = encode_rgbm(linear.pixelf(x, y));
            std::copy(t.begin(), t.end(), out.pixel8(x, y));
        }
    return out;
}

}  // namespace puddle::assets
