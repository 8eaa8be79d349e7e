#pragma once
// Environment pictures the tests make themselves: float files through OpenImageIO, panoramas from a
// function of direction, and a night skyline with HDR windows (docs/environments.md's HDR picture).

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "assets/image.hpp"
#include "assets/image_io.hpp"
#include "assets/procedural.hpp"

namespace puddle::test {

// .hdr / .exr / .tif as float, as panorama tools write them.
inline void write_float_image(const std::string& path, const assets::Image& img) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    // RGB only: Radiance .hdr has no alpha. The image's RGBA rows are read with a 16-byte pixel stride.
    const OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, img.data.data(), 4 * sizeof(float)))
        << out->geterror();
    ASSERT_TRUE(out->close());
}

// The direction a panorama texel centre looks along: u = 0.5 faces -Z, u = 0.75 faces +X, the top row +Y
// (the convention of equirect_to_cube.frag, written here from the definition, not from the shader).
inline glm::vec3 panorama_direction(int x, int y, int width, int height) {
    const double pi = 3.14159265358979;
    const double lon = ((x + 0.5) / width - 0.5) * 2.0 * pi;
    const double lat = (0.5 - (y + 0.5) / height) * pi;
    return glm::vec3(float(std::sin(lon) * std::cos(lat)), float(std::sin(lat)),
                     float(-std::cos(lon) * std::cos(lat)));
}

inline assets::Image panorama_of(int width, const std::function<glm::vec3(glm::vec3)>& radiance) {
    assets::Image img = assets::Image::make(width, width / 2, assets::PixelFormat::RGBA32F);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::vec3 c = radiance(panorama_direction(x, y, img.width, img.height));
            float* p = img.pixelf(x, y);
            p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
        }
    return img;
}

inline float srgb_to_linear(std::uint8_t v) {
    const float c = v / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float hash01(int a, int b) {
    unsigned h = unsigned(a) * 374761393u + unsigned(b) * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return float(h ^ (h >> 16)) / 4294967295.0f;
}

// A city at night: a deep blue sky fading to an orange glow at the horizon, dark towers, and lit windows
// 4 to 16 times brighter than white, so their reflections in the ripples stay bright glints.
inline assets::Image city_lights_panorama(int width = 1024) {
    const float pi = 3.14159265f;
    return panorama_of(width, [pi](glm::vec3 d) {
        const float lon = std::atan2(d.x, -d.z), lat = std::asin(std::clamp(d.y, -1.0f, 1.0f));
        const float up = std::max(d.y, 0.0f);
        glm::vec3 sky = glm::mix(glm::vec3(0.25f, 0.10f, 0.04f), glm::vec3(0.004f, 0.008f, 0.03f),
                                 std::pow(std::min(up * 3.0f, 1.0f), 0.5f));
        if (d.y < 0.0f) return glm::vec3(0.01f, 0.008f, 0.006f);  // the street
        // Towers: one every 1/48 of a turn, of hashed height and width.
        const int slot = int(std::floor((lon / (2.0f * pi) + 0.5f) * 48.0f));
        const float within = (lon / (2.0f * pi) + 0.5f) * 48.0f - float(slot);
        const float height = 0.08f + 0.45f * hash01(slot, 1);
        const float margin = 0.1f + 0.25f * hash01(slot, 2);
        if (lat < height && within > margin && within < 1.0f - margin) {
            const int column = int(std::floor(within * 14.0f)), row = int(std::floor(lat * 90.0f));
            const bool window =
                (column % 2 == 1) && (row % 2 == 1) && hash01(slot * 131 + column, row) > 0.55f;
            if (!window) return glm::vec3(0.006f, 0.006f, 0.008f);
            const float warmth = hash01(column, slot * 17 + row);
            return glm::mix(glm::vec3(4.0f, 3.2f, 2.0f), glm::vec3(16.0f, 11.0f, 6.0f), warmth);
        }
        // A moon, far brighter than anything an 8-bit sky can hold.
        const glm::vec3 moon = glm::normalize(glm::vec3(-0.55f, 0.45f, -0.7f));
        if (glm::dot(d, moon) > 0.9993f) return glm::vec3(30.0f, 29.0f, 26.0f);
        return sky;
    });
}

// The procedural night sky as six 8-bit sRGB faces (px.png ... nz.png) in `folder`, clipped at white: for
// tests that compare two paths which would otherwise store the HDR sky differently (half floats against
// RGBM, or the camera's 8-bit cube), so that only the path under test differs. Returns the folder.
inline std::string write_ldr_night_sky(const std::string& folder, int face_size = 256) {
    const assets::CubeImages sky = assets::night_sky_cubemap(face_size);
    for (std::size_t f = 0; f < 6; ++f)
        EXPECT_TRUE(assets::write_png(folder + "/" + assets::cube_face_names[f] + ".png",
                                      assets::to_srgb8(sky.faces[f]))
                        .ok());
    return folder;
}

// A smooth 8-bit sky written to `path` (PNG panorama): a dark blue zenith, a warm horizon, a grey street.
// For tests of geometry (where the water meets a ray, how steep a ripple is) whose pixel differences
// would otherwise depend on how sharp the night city's lit windows are. Returns the path.
inline std::string write_smooth_sky(const std::string& path) {
    const assets::Image sky = panorama_of(256, [](glm::vec3 d) {
        if (d.y < 0.0f) return glm::vec3(0.10f, 0.08f, 0.06f);
        return glm::mix(glm::vec3(0.30f, 0.20f, 0.15f), glm::vec3(0.02f, 0.03f, 0.08f), std::sqrt(d.y));
    });
    EXPECT_TRUE(assets::write_png(path, assets::to_srgb8(sky)).ok());
    return path;
}

}  // namespace puddle::test
