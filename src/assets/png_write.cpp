// write_png (image_io.hpp) through libpng's simplified API, so a run that only writes its screenshot
// never loads the OpenImageIO module and its libraries.

#include <png.h>

#include <filesystem>
#include <system_error>

#include "assets/image_io.hpp"

namespace puddle::assets {

Result<void> write_png(const std::string& path, const Image& image) {
    if (image.empty() || image.format != PixelFormat::RGBA8)
        return make_error(ExitCode::Asset,
                          "image: {}: cannot write: only non-empty RGBA8 images are written as PNG", path);

    // Written beside the target and renamed, so a failed write never leaves a truncated PNG behind.
    const std::string tmp = path + ".tmp";
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGBA;  // 8-bit sRGB with straight alpha, as Image holds it
    if (png_image_write_to_file(&png, tmp.c_str(), 0, image.data.data(), 0, nullptr) == 0) {
        const std::string reason = png.message[0] != '\0' ? png.message : "unknown error";
        png_image_free(&png);
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, reason);
    }

    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, ec.message());
    }
    return {};
}

}  // namespace puddle::assets
