#pragma once
// A CPU-side image: tightly packed rows, top row first, RGBA, 8-bit (sRGB-encoded colour) or 32-bit
// float (linear, for HDR). Produced by the loaders and the procedural generators; uploaded by systems.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace puddle::assets {

enum class PixelFormat { RGBA8, RGBA32F };

struct Image {
    int width = 0;
    int height = 0;
    PixelFormat format = PixelFormat::RGBA8;
    std::vector<std::uint8_t> data;  // width * height * bytes_per_pixel()

    static Image make(int w, int h, PixelFormat f = PixelFormat::RGBA8);
    std::size_t bytes_per_pixel() const { return format == PixelFormat::RGBA8 ? 4 : 16; }
    bool empty() const { return width == 0 || height == 0; }
    std::uint8_t* pixel8(int x, int y) { return data.data() + (std::size_t(y) * width + x) * 4; }
    const std::uint8_t* pixel8(int x, int y) const { return data.data() + (std::size_t(y) * width + x) * 4; }
    float* pixelf(int x, int y) {
        return reinterpret_cast<float*>(data.data()) + (std::size_t(y) * width + x) * 4;
    }
    const float* pixelf(int x, int y) const {
        return reinterpret_cast<const float*>(data.data()) + (std::size_t(y) * width + x) * 4;
    }
};

// An 8-bit sRGB image as linear RGBA32F (a float image is returned as it is).
Image to_linear_float(const Image& image);
// A linear RGBA32F image as 8-bit sRGB (clamped to 0..1); an RGBA8 image is returned as it is.
Image to_srgb8(const Image& image);
// Half the size in each direction (odd edges dropped), averaging 2x2 blocks; for pictures larger than
// the GPU takes. Averages in the stored encoding: fine for a one-off shrink.
Image halve(const Image& image);

// Faces in GL order: +X, -X, +Y, -Y, +Z, -Z (file names px, nx, py, ny, pz, nz). Rows top first, as
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + i expects them (no vertical flip).
struct CubeImages {
    std::array<Image, 6> faces;
    std::string source;  // for logs: a folder, "procedural night sky", ...
};
inline constexpr std::array<const char*, 6> cube_face_names{"px", "nx", "py", "ny", "pz", "nz"};

}  // namespace puddle::assets
