// libpuddle-images.so: reading images through OpenImageIO (PNG through libpng: assets/png_reader.hpp),
// behind the C interface of image_module_abi.h. Built as its own module so that only runs which read an image
// file map OpenImageIO and its dependencies (image_module.cpp loads it). Only the entry point is exported.

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "assets/image_module_abi.h"
#include "assets/orientation.hpp"
#include "assets/png_reader.hpp"

namespace {

// OIIO errors can span lines and repeat; our messages are one line.
std::string one_line(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? "unknown error" : text;
}

int fail(char* error, std::size_t error_size, const std::string& why) {
    if (error_size > 0) std::snprintf(error, error_size, "%s", why.c_str());
    return 0;
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

bool is_float_type(OIIO::TypeDesc type) {
    return type.basetype == OIIO::TypeDesc::FLOAT || type.basetype == OIIO::TypeDesc::HALF ||
           type.basetype == OIIO::TypeDesc::DOUBLE;
}

// Opens `path` and checks its header; ImageInput::open reads the header only, no pixels. Null, with
// `why` set, for a file that cannot be opened or is no flat 2D image.
std::unique_ptr<OIIO::ImageInput> open_checked(const char* path, std::string& why) {
    // Textures keep straight alpha: without this hint OIIO premultiplies PNG/TGA colour by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        why = "cannot read: " + one_line(OIIO::geterror());
        return nullptr;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        why = "empty image (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) + ", " +
              std::to_string(spec.nchannels) + " channels)";
        return nullptr;
    }
    if (spec.depth > 1 || spec.deep) {
        why = "volume and deep images are not supported";
        return nullptr;
    }
    return in;
}

// The EXIF/TIFF orientation OpenImageIO read from the file's metadata (1, upright, when it has none).
int orientation_of(const OIIO::ImageSpec& spec) {
    return puddle::assets::valid_orientation(spec.get_int_attribute("Orientation", 1));
}

// Expands `raw` to RGBA in `dst`, turned upright when `orientation` says the file was stored turned.
template <class T>
void to_upright_rgba(const std::vector<T>& raw, int channels, const OIIO::ImageSpec& spec, int orientation,
                     T opaque, T* dst) {
    const std::size_t w = static_cast<std::size_t>(spec.width), h = static_cast<std::size_t>(spec.height);
    if (orientation == 1) return expand_to_rgba<T>(raw, channels, w * h, opaque, dst);
    std::vector<T> stored(w * h * 4);
    expand_to_rgba<T>(raw, channels, w * h, opaque, stored.data());
    puddle::assets::orient_pixels(stored.data(), w, h, 4, orientation, dst);
}

int probe(const char* path, PuddleImageInfo* info, char* error, std::size_t error_size) {
    std::string why;
    if (puddle::assets::png::has_signature(path))
        return puddle::assets::png::probe(path, info, why) ? 1 : fail(error, error_size, why);
    auto in = open_checked(path, why);
    if (!in) return fail(error, error_size, why);
    const OIIO::ImageSpec& spec = in->spec();
    const bool swap = puddle::assets::orientation_swaps_axes(orientation_of(spec));  // the size as shown
    *info = PuddleImageInfo{.width = swap ? spec.height : spec.width,
                            .height = swap ? spec.width : spec.height,
                            .is_float = is_float_type(spec.format) ? 1 : 0};
    return 1;
}

int read(const char* path, int want, PuddleImageAlloc alloc, void* context, char* error,
         std::size_t error_size) {
    std::string why;
    if (puddle::assets::png::has_signature(path))
        return puddle::assets::png::read(path, want, alloc, context, why) ? 1 : fail(error, error_size, why);
    auto in = open_checked(path, why);
    if (!in) return fail(error, error_size, why);
    const OIIO::ImageSpec& spec = in->spec();

    const bool as_float =
        want == PUDDLE_IMAGE_RGBA32F || (want == PUDDLE_IMAGE_AS_STORED && is_float_type(spec.format));
    // Pixels are handed over upright (orientation.hpp), in the size viewers show.
    const int orientation = orientation_of(spec);
    const bool swap = puddle::assets::orientation_swaps_axes(orientation);
    void* dst =
        alloc(context, swap ? spec.height : spec.width, swap ? spec.width : spec.height, as_float ? 1 : 0);
    if (dst == nullptr) return fail(error, error_size, "cannot read: no memory for the pixels");

    // Channels past RGBA (depth, extra AOVs) are never read.
    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    // OIIO converts the file's type to ours (e.g. 16-bit to 8-bit with rounding, 65535 -> 255).
    bool ok = false;
    if (!as_float) {
        std::vector<std::uint8_t> raw(pixels * static_cast<std::size_t>(channels));
        ok = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data());
        if (ok)
            to_upright_rgba<std::uint8_t>(raw, channels, spec, orientation, 255,
                                          static_cast<std::uint8_t*>(dst));
    } else {
        std::vector<float> raw(pixels * static_cast<std::size_t>(channels));
        ok = in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data());
        if (ok) to_upright_rgba<float>(raw, channels, spec, orientation, 1.0f, static_cast<float*>(dst));
    }
    // Some readers (JPEG) pad a truncated file and only record an error: treat that as corrupt too.
    if (ok && in->has_error()) ok = false;
    if (!ok) {
        std::string reason = in->geterror();
        if (reason.empty()) reason = OIIO::geterror();
        return fail(error, error_size, "cannot decode: " + one_line(reason));
    }
    in->close();
    return 1;
}

// Any exception (std::bad_alloc in a huge image) stays on this side of the C interface.
int read_noexcept(const char* path, int want, PuddleImageAlloc alloc, void* context, char* error,
                  std::size_t error_size) noexcept {
    try {
        return read(path, want, alloc, context, error, error_size);
    } catch (const std::exception& e) {
        return fail(error, error_size, std::string("cannot read: ") + e.what());
    } catch (...) {
        return fail(error, error_size, "cannot read: unknown error");
    }
}

int probe_noexcept(const char* path, PuddleImageInfo* info, char* error, std::size_t error_size) noexcept {
    try {
        return probe(path, info, error, error_size);
    } catch (const std::exception& e) {
        return fail(error, error_size, std::string("cannot read: ") + e.what());
    } catch (...) {
        return fail(error, error_size, "cannot read: unknown error");
    }
}

constexpr PuddleImageModule module{
    .abi_version = PUDDLE_IMAGE_MODULE_ABI_VERSION,
    .read = read_noexcept,
    .probe = probe_noexcept,
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const PuddleImageModule* puddle_image_module() {
    return &module;
}
