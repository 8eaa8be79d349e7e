#include "systems/remote/screenshot_jpeg.hpp"

#include <algorithm>
#include <span>

#include "camera/mjpeg_encoder.hpp"

namespace puddle::systems {

std::string scaled_rgb(const assets::Image& frame, int width, int height) {
    std::string rgb(static_cast<std::size_t>(width) * height * 3, '\0');
    for (int y = 0; y < height; ++y) {
        const int y0 = y * frame.height / height, y1 = std::max(y0 + 1, (y + 1) * frame.height / height);
        for (int x = 0; x < width; ++x) {
            const int x0 = x * frame.width / width, x1 = std::max(x0 + 1, (x + 1) * frame.width / width);
            unsigned sum[3] = {0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx) {
                    const std::uint8_t* p = frame.pixel8(sx, sy);
                    for (int c = 0; c < 3; ++c) sum[c] += p[c];
                }
            const unsigned n = static_cast<unsigned>((y1 - y0) * (x1 - x0));
            for (int c = 0; c < 3; ++c)
                rgb[(static_cast<std::size_t>(y) * width + x) * 3 + c] =
                    static_cast<char>((sum[c] + n / 2) / n);
        }
    }
    return rgb;
}

std::string screenshot_jpeg(const assets::Image& frame, int max_width) {
    if (frame.empty() || frame.format != assets::PixelFormat::RGBA8) return {};
    const int width = std::min(frame.width, std::max(1, max_width));
    const int height = std::max(1, static_cast<int>(static_cast<long>(frame.height) * width / frame.width));
    const std::string rgb = scaled_rgb(frame, width, height);
    const auto jpeg =
        camera::encode_jpeg(std::span(reinterpret_cast<const std::uint8_t*>(rgb.data()), rgb.size()), width,
                            height, screenshot_jpeg_quality);
    return {reinterpret_cast<const char*>(jpeg.data()), jpeg.size()};
}

}  // namespace puddle::systems
