#include "systems/sky/cloud_layer_system.hpp"

#include <cmath>
#include <span>

#include "assets/procedural.hpp"

namespace puddle::systems {

using params::ParamId;

Result<void> build_clouds(gpu::Device& device, Clouds& clouds) {
    assets::Image level = assets::cloud_layer_image();
    const int levels = gpu::full_mip_count(level.width);
    auto texture = device.create_texture({.label = "cloud layer",
                                          .format = gpu::TextureFormat::RGBA8,
                                          .width = level.width,
                                          .height = level.height,
                                          .mip_levels = levels});
    if (!texture) return texture.error();
    clouds.layer = std::move(texture).value();
    // The mip chain made here, by 2x2 averages (it tiles, and coverage averages as it should), so start-up
    // renders nothing for it (llvmpipe's mipmap pass over it crashed under QEMU's AVX2: tests/vm/run).
    for (int i = 0; i < levels; ++i) {
        if (i > 0) level = assets::halve(level);
        clouds.layer.upload(std::as_bytes(std::span(level.data)), i);
    }
    clouds.sampler =
        device.create_sampler({.label = "cloud layer", .mipmaps = true, .wrap = gpu::Wrap::Repeat});
    clouds.light = assets::night_sky_cloud_light();
    return {};
}

void cloud_drift_system(const params::Params& params, const FrameClock& clock, Clouds& clouds) {
    // Deck heights a second, in tiles; the direction is fixed, toward +x and +z.
    const double tiles_per_second = static_cast<double>(params.get<ParamId::environment_cloud_drift>()) /
                                    60.0 / static_cast<double>(assets::cloud_tile_units);
    const double travelled = clock.sim_time * tiles_per_second;
    const double along_x = travelled * 0.8, along_z = travelled * 0.6;
    clouds.offset = glm::vec2(static_cast<float>(along_x - std::floor(along_x)),
                              static_cast<float>(along_z - std::floor(along_z)));
}

}  // namespace puddle::systems
