#include "assets/image.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::assets {

Image Image::make(int w, int h, PixelFormat f) {
    Image img;
    img.width = w;
    img.height = h;
    img.format = f;
    img.data.assign(std::size_t(w) * h * img.bytes_per_pixel(), 0);
    return img;
}

Image to_linear_float(const Image& image) {
    if (image.format == PixelFormat::RGBA32F) return image;
    Image out = Image::make(image.width, image.height, PixelFormat::RGBA32F);
    auto linear = [](std::uint8_t v) {
        const float c = v / 255.0f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* s = image.pixel8(x, y);
            float* d = out.pixelf(x, y);
            d[0] = linear(s[0]), d[1] = linear(s[1]), d[2] = linear(s[2]), d[3] = s[3] / 255.0f;
        }
    return out;
}

Image to_srgb8(const Image& image) {
    if (image.format == PixelFormat::RGBA8) return image;
    Image out = Image::make(image.width, image.height, PixelFormat::RGBA8);
    auto encode = [](float v) {
        const float c = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f);
        const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
        return static_cast<std::uint8_t>(std::lround(e * 255.0f));
    };
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* s = image.pixelf(x, y);
            std::uint8_t* d = out.pixel8(x, y);
            d[0] = encode(s[0]), d[1] = encode(s[1]), d[2] = encode(s[2]);
            d[3] = static_cast<std::uint8_t>(std::lround(std::clamp(s[3], 0.0f, 1.0f) * 255.0f));
        }
    return out;
}

Image halve(const Image& image) {
    Image out = Image::make(std::max(1, image.width / 2), std::max(1, image.height / 2), image.format);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int x0 = std::min(2 * x, image.width - 1), x1 = std::min(2 * x + 1, image.width - 1);
                const int y0 = std::min(2 * y, image.height - 1), y1 = std::min(2 * y + 1, image.height - 1);
                if (image.format == PixelFormat::RGBA8) {
                    const int sum = image.pixel8(x0, y0)[c] + image.pixel8(x1, y0)[c] +
                                    image.pixel8(x0, y1)[c] + image.pixel8(x1, y1)[c];
                    out.pixel8(x, y)[c] = static_cast<std::uint8_t>((sum + 2) / 4);
                } else {
                    out.pixelf(x, y)[c] = 0.25f * (image.pixelf(x0, y0)[c] + image.pixelf(x1, y0)[c] +
                                                   image.pixelf(x0, y1)[c] + image.pixelf(x1, y1)[c]);
                }
            }
    return out;
}

}  // namespace puddle::assets
