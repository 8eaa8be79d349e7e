#include "assets/image_limits.hpp"

namespace puddle::assets {

Result<void> check_image_size(const std::string& path, int width, int height, PixelFormat format) {
    if (width <= 0 || height <= 0)
        return make_error(ExitCode::Asset, "image: {}: empty image ({}x{})", path, width, height);
    if (width > max_image_side || height > max_image_side)
        return make_error(ExitCode::Asset, "image: {}: {}x{} is too large: at most {} pixels a side", path,
                          width, height, max_image_side);
    const std::size_t bytes_per_pixel = format == PixelFormat::RGBA8 ? 4 : 16;
    const std::size_t bytes =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * bytes_per_pixel;
    if (bytes > max_image_bytes)
        return make_error(ExitCode::Asset,
                          "image: {}: {}x{} {} needs {} MiB decoded, more than the {} MiB limit", path, width,
                          height, format == PixelFormat::RGBA8 ? "RGBA8" : "RGBA32F", bytes >> 20,
                          max_image_bytes >> 20);
    return {};
}

}  // namespace puddle::assets
