#include "app/screenshot_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "assets/image_io.hpp"
#include "systems/remote/screenshot_jpeg.hpp"

namespace puddle::app {

ScreenshotFormat screenshot_format(std::string_view path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".jpg" || ext == ".jpeg" ? ScreenshotFormat::jpeg : ScreenshotFormat::png;
}

namespace {

Result<void> write_jpeg(const std::string& path, const assets::Image& image) {
    const std::string jpeg = systems::screenshot_jpeg(image, image.width);
    if (jpeg.empty())
        return make_error(ExitCode::Asset,
                          "image: {}: cannot write: only non-empty RGBA8 images are written as JPEG", path);
    const std::string tmp = path + ".tmp";
    std::error_code ignored;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (out) out.write(jpeg.data(), static_cast<std::streamsize>(jpeg.size()));
        if (!out || !out.flush()) {
            std::filesystem::remove(tmp, ignored);
            return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path,
                              std::generic_category().message(errno));
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ignored);
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, ec.message());
    }
    return {};
}

}  // namespace

Result<void> write_screenshot(const std::string& path, const assets::Image& image) {
    return screenshot_format(path) == ScreenshotFormat::jpeg ? write_jpeg(path, image)
                                                             : assets::write_png(path, image);
}

}  // namespace puddle::app
