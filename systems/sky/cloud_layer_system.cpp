#include "systems/sky/cloud_layer_system.hpp"

#include <cmath>
#include <span>

#include "assets/procedural.hpp"

namespace puddle::systems {

using params::ParamId;

Result<void> build_clouds(gpu::Device& device, Clouds& clouds) {
    const assets::Image image = assets::cloud_layer_image();
    auto texture = device.create_texture({.label = "cloud layer",
                                          .format = gpu::TextureFormat::RGBA8,
                                          .width = image.width,
                                          .height = image.height,
                                          .mip_levels = gpu::full_mip_count(image.width)});
    if (!texture) return texture.error();
    clouds.layer = std::move(texture).value();
    clouds.layer.upload(std::as_bytes(std::span(image.data)));
    clouds.layer.generate_mipmaps();
    clouds.sampler =
        device.create_sampler({.label = "cloud layer", .mipmaps = true, .wrap = gpu::Wrap::Repeat});
    clouds.light = assets::night_sky_cloud_light();
    return {};
}

void cloud_drift_system(const params::Params& params, const FrameClock& clock, Clouds& clouds) {
    // Deck heights a second, in tiles; the direction is fixed (a wind from the north-west).
    const double tiles_per_second = static_cast<double>(params.get<ParamId::environment_cloud_drift>()) /
                                    60.0 / static_cast<double>(assets::cloud_tile_units);
    const double travelled = clock.sim_time * tiles_per_second;
    const double along_x = travelled * 0.8, along_z = travelled * 0.6;
    clouds.offset = glm::vec2(static_cast<float>(along_x - std::floor(along_x)),
                              static_cast<float>(along_z - std::floor(along_z)));
}

}  // namespace puddle::systems
