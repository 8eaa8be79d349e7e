#pragma once
// What `environment.image` names, read from disk: a folder of six faces, six paths joined by '|', a cube
// cross in one image, or an equirectangular panorama (2:1) that the GPU turns into a cube at load.
// 8-bit files stay sRGB-encoded RGBA8; float files (.hdr, .exr) stay linear RGBA32F.

#include <optional>
#include <string>

#include "assets/image.hpp"
#include "assets/procedural.hpp"
#include "util/result.hpp"

namespace puddle::assets {

struct EnvironmentImages {
    std::optional<CubeImages> faces;  // six faces, ready to upload
    Image panorama;                   // otherwise: an equirectangular panorama, width = 2 * height
    std::string source;               // for logs

    bool hdr() const {
        return faces ? faces->faces[0].format == PixelFormat::RGBA32F
                     : panorama.format == PixelFormat::RGBA32F;
    }
};

// Empty `spec`: the procedural night sky, made with faces of `procedural_face_size` (clamped to 1 to
// procedural_sky_max_face_size).
// procedural_clouds: whether the procedural sky's clouds are baked in or left to the drifting layer.
Result<EnvironmentImages> load_environment_images(const std::string& spec,
                                                  int procedural_face_size = procedural_sky_face_size,
                                                  SkyClouds procedural_clouds = SkyClouds::baked);

}  // namespace puddle::assets
