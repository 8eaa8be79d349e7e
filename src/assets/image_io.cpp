#include "assets/image_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <system_error>

#include "assets/image_limits.hpp"
#include "assets/image_module.hpp"
#include "util/unique_fd.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

// OIIO's "could not open" hides errno; ask the OS first so a missing file reads as one (and needs no
// image module).
// Only a regular file goes to the decoder: OpenImageIO opening a FIFO would wait for a writer (a
// `mock:` camera folder holding one hung start-up), and a device would be read for ever.
Result<void> check_readable(const std::string& path) {
    UniqueFd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (!fd) {
        const int err = errno;
        return make_error(ExitCode::Asset, "image: {}: cannot open: {}", path,
                          std::generic_category().message(err));
    }
    struct stat st {};
    const bool stated = ::fstat(fd.get(), &st) == 0;
    fd.reset();
    if (stated && S_ISDIR(st.st_mode))
        return make_error(ExitCode::Asset, "image: {}: cannot open: is a directory", path);
    if (stated && !S_ISREG(st.st_mode))
        return make_error(ExitCode::Asset, "image: {}: cannot open: {}, not a file", path,
                          S_ISFIFO(st.st_mode) ? "is a FIFO" : "is a device or socket");
    return {};
}

// What the module's allocation callback works on: the image to size, and why it refused to.
struct Allocation {
    const std::string& path;
    Image image;
    std::optional<Error> refused;  // the size is past image_limits.hpp's limits
};

// The module's PuddleImageAlloc: called once the module has read the file's header, before any pixel is
// decoded. Checks the size against the limits, then sizes the Image.
void* allocate(void* context, int width, int height, int is_float) noexcept {
    auto* a = static_cast<Allocation*>(context);
    try {
        const PixelFormat format = is_float ? PixelFormat::RGBA32F : PixelFormat::RGBA8;
        if (auto fits = check_image_size(a->path, width, height, format); !fits) {
            a->refused = fits.error();
            return nullptr;
        }
        a->image = Image::make(width, height, format);
        return a->image.data.data();
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

Result<Image> read_through_module(const std::string& path, PuddleImageWant want) {
    if (auto readable = check_readable(path); !readable) return readable.error();
    auto module = image_module();
    if (!module)
        return make_error(ExitCode::Asset, "image: {}: cannot read: {}", path, module.error().message);
    Allocation allocation{.path = path};
    char why[512] = "";
    if ((*module)->read(path.c_str(), want, allocate, &allocation, why, sizeof why) == 0) {
        if (allocation.refused) return *allocation.refused;
        return make_error(ExitCode::Asset, "image: {}: {}", path, why);
    }
    return std::move(allocation.image);
}

Result<ImageInfo> probe_through_module(const std::string& path, PuddleImageWant want) {
    if (auto readable = check_readable(path); !readable) return readable.error();
    auto module = image_module();
    if (!module)
        return make_error(ExitCode::Asset, "image: {}: cannot read: {}", path, module.error().message);
    PuddleImageInfo header{};
    char why[512] = "";
    if ((*module)->probe(path.c_str(), &header, why, sizeof why) == 0)
        return make_error(ExitCode::Asset, "image: {}: {}", path, why);
    const bool as_float = want == PUDDLE_IMAGE_RGBA32F || (want == PUDDLE_IMAGE_AS_STORED && header.is_float);
    const ImageInfo info{.width = header.width,
                         .height = header.height,
                         .format = as_float ? PixelFormat::RGBA32F : PixelFormat::RGBA8};
    if (auto fits = check_image_size(path, info.width, info.height, info.format); !fits) return fits.error();
    return info;
}

}  // namespace

Result<ImageInfo> probe_image(const std::string& path, PixelFormat want) {
    return probe_through_module(path, want == PixelFormat::RGBA8 ? PUDDLE_IMAGE_RGBA8 : PUDDLE_IMAGE_RGBA32F);
}

Result<ImageInfo> probe_color_image(const std::string& path) {
    return probe_through_module(path, PUDDLE_IMAGE_AS_STORED);
}

Result<Image> read_image(const std::string& path, PixelFormat want) {
    return read_through_module(path, want == PixelFormat::RGBA8 ? PUDDLE_IMAGE_RGBA8 : PUDDLE_IMAGE_RGBA32F);
}

Result<Image> read_color_image(const std::string& path) {
    auto image = read_through_module(path, PUDDLE_IMAGE_AS_STORED);
    if (!image || image->format != PixelFormat::RGBA32F) return image;
    // 65504 is the largest half float: a sun brighter than that still reads as very bright, not infinite.
    float* v = image->pixelf(0, 0);
    for (std::size_t i = 0, n = std::size_t(image->width) * image->height * 4; i < n; ++i)
        v[i] = std::isfinite(v[i]) ? std::clamp(v[i], 0.0f, 65504.0f) : (v[i] > 0 ? 65504.0f : 0.0f);
    return image;
}

}  // namespace puddle::assets
