#include "assets/image_io.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

// OIIO errors can span lines and repeat; our messages are one line.
std::string one_line(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? "unknown error" : text;
}

// OIIO's "could not open" hides errno; ask the OS first so a missing file reads as one.
Result<void> check_readable(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
        return make_error(ExitCode::Asset, "image: {}: cannot open: is a directory", path);
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (f == nullptr) {
        const int err = errno;
        return make_error(ExitCode::Asset, "image: {}: cannot open: {}", path,
                          std::generic_category().message(err));
    }
    std::fclose(f);
    return {};
}

// Expands 1 (grey), 2 (grey, alpha), 3 (RGB) or 4+ channels into RGBA. `opaque` is alpha's full value.
template <class T>
void expand_to_rgba(const std::vector<T>& src, int channels, std::size_t pixels, T opaque, T* dst) {
    for (std::size_t i = 0; i < pixels; ++i) {
        const T* s = src.data() + i * static_cast<std::size_t>(channels);
        T* d = dst + i * 4;
        switch (channels) {
            case 1:
                d[0] = d[1] = d[2] = s[0];
                d[3] = opaque;
                break;
            case 2:
                d[0] = d[1] = d[2] = s[0];
                d[3] = s[1];
                break;
            case 3:
                d[0] = s[0];
                d[1] = s[1];
                d[2] = s[2];
                d[3] = opaque;
                break;
            default:
                d[0] = s[0];
                d[1] = s[1];
                d[2] = s[2];
                d[3] = s[3];
                break;
        }
    }
}

}  // namespace

Result<Image> read_image(const std::string& path, PixelFormat want) {
    if (auto readable = check_readable(path); !readable) return readable.error();

    // Textures keep straight alpha: without this hint OIIO premultiplies PNG/TGA colour by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in)
        return make_error(ExitCode::Asset, "image: {}: cannot read: {}", path, one_line(OIIO::geterror()));

    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return make_error(ExitCode::Asset, "image: {}: empty image ({}x{}, {} channels)", path, spec.width,
                          spec.height, spec.nchannels);
    if (spec.depth > 1 || spec.deep)
        return make_error(ExitCode::Asset, "image: {}: volume and deep images are not supported", path);

    // Channels past RGBA (depth, extra AOVs) are never read.
    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    Image image = Image::make(spec.width, spec.height, want);

    // OIIO converts the file's type to ours (e.g. 16-bit to 8-bit with rounding, 65535 -> 255).
    bool ok = false;
    if (want == PixelFormat::RGBA8) {
        std::vector<std::uint8_t> raw(pixels * static_cast<std::size_t>(channels));
        ok = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data());
        if (ok) expand_to_rgba<std::uint8_t>(raw, channels, pixels, 255, image.data.data());
    } else {
        std::vector<float> raw(pixels * static_cast<std::size_t>(channels));
        ok = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data());
        if (ok) expand_to_rgba<float>(raw, channels, pixels, 1.0f, image.pixelf(0, 0));
    }
    // Some readers (JPEG) pad a truncated file and only record an error: treat that as corrupt too.
    if (ok && in->has_error()) ok = false;
    if (!ok) {
        std::string reason = in->geterror();
        if (reason.empty()) reason = OIIO::geterror();
        return make_error(ExitCode::Asset, "image: {}: cannot decode: {}", path, one_line(reason));
    }
    in->close();
    return image;
}

Result<Image> read_color_image(const std::string& path) {
    bool is_float = false;
    {
        if (auto readable = check_readable(path); !readable) return readable.error();
        auto in = OIIO::ImageInput::open(path);
        if (!in)
            return make_error(ExitCode::Asset, "image: {}: cannot read: {}", path, one_line(OIIO::geterror()));
        const OIIO::TypeDesc type = in->spec().format;
        is_float = type.basetype == OIIO::TypeDesc::FLOAT || type.basetype == OIIO::TypeDesc::HALF ||
                   type.basetype == OIIO::TypeDesc::DOUBLE;
    }
    auto image = read_image(path, is_float ? PixelFormat::RGBA32F : PixelFormat::RGBA8);
    if (!image || !is_float) return image;
    // 65504 is the largest half float: a sun brighter than that still reads as very bright, not infinite.
    float* v = image->pixelf(0, 0);
    for (std::size_t i = 0, n = std::size_t(image->width) * image->height * 4; i < n; ++i)
        v[i] = std::isfinite(v[i]) ? std::clamp(v[i], 0.0f, 65504.0f) : (v[i] > 0 ? 65504.0f : 0.0f);
    return image;
}

Result<void> write_png(const std::string& path, const Image& image) {
    if (image.empty() || image.format != PixelFormat::RGBA8)
        return make_error(ExitCode::Asset,
                          "image: {}: cannot write: only non-empty RGBA8 images are written as PNG", path);

    // Written beside the target and renamed, so a failed write never leaves a truncated PNG behind.
    const std::string tmp = path + ".tmp";
    auto out = OIIO::ImageOutput::create("png");
    if (!out)
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, one_line(OIIO::geterror()));

    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // our alpha is straight: do not un-premultiply on write
    bool ok = out->open(tmp, spec) && out->write_image(OIIO::TypeDesc::UINT8, image.data.data());
    std::string reason = ok ? std::string() : out->geterror();
    ok = out->close() && ok;
    if (!ok) {
        if (reason.empty()) reason = out->geterror();
        if (reason.empty()) reason = OIIO::geterror();
        std::error_code ignored;
        fs::remove(tmp, ignored);
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, one_line(reason));
    }

    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        return make_error(ExitCode::Asset, "image: {}: cannot write: {}", path, ec.message());
    }
    return {};
}

}  // namespace puddle::assets
