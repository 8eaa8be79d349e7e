#pragma once
// Reading images through OpenImageIO, which libpuddle-images.so wraps and image_module.hpp loads on the
// first read; writing PNG with libpng. Errors name the path and the reason; the app turns them into exit
// code 3 at start-up.

#include <cstddef>
#include <string>

#include "assets/image.hpp"
#include "util/result.hpp"

namespace puddle::assets {

// Any format OpenImageIO reads. RGBA8 output converts to 8 bits (grey and RGB gain channels, alpha 255);
// RGBA32F output keeps the file's values (linear for HDR formats).
Result<Image> read_image(const std::string& path, PixelFormat want = PixelFormat::RGBA8);
// Colour as the file stores it: float files (.hdr, .exr, float TIFF) as RGBA32F linear radiance, with
// negative, NaN and beyond-half-float values clamped so they upload safely; integer files (8 or 16 bits)
// as RGBA8, sRGB-encoded.
Result<Image> read_color_image(const std::string& path);
// What a file's header says, read without decoding a pixel (ImageInput::open through the module): the
// size and the format the matching read_* call would return. Callers check their own size and shape
// rules against it first, so a file that would be refused costs a header read, not a decode.
struct ImageInfo {
    int width = 0;   // pixels
    int height = 0;  // pixels
    PixelFormat format = PixelFormat::RGBA8;

    std::size_t decoded_bytes() const {
        return std::size_t(width) * std::size_t(height) * (format == PixelFormat::RGBA8 ? 4 : 16);
    }
};
// The header of what read_image(path, want) / read_color_image(path) would read. Errors are the ones
// those give for a missing, unreadable or unrecognised file, or one past image_limits.hpp's limits.
Result<ImageInfo> probe_image(const std::string& path, PixelFormat want = PixelFormat::RGBA8);
Result<ImageInfo> probe_color_image(const std::string& path);
// PNG, 8 bits per channel, RGBA.
Result<void> write_png(const std::string& path, const Image& image);

}  // namespace puddle::assets
