#include "systems/equirect_to_cube.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <span>

namespace puddle::systems {
namespace {

int mip_count(int size) {
    return std::bit_width(static_cast<unsigned>(std::max(size, 1)));
}

}  // namespace

int auto_face_size(int panorama_width, int max_cube_size) {
    return std::clamp(panorama_width / 4, 1, std::min(1024, max_cube_size));
}

Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& source, int face_size,
                                      gpu::TextureFormat format, bool rgbm) {
    // A panorama wider than the GPU takes is shrunk first (8k and 16k panoramas exist; many GPUs stop at 4k).
    const assets::Image* panorama = &source;
    assets::Image shrunk;
    while (panorama->width > device.caps().max_texture_size) {
        shrunk = assets::halve(*panorama);
        panorama = &shrunk;
    }
    if (panorama != &source)
        spdlog::info("environment: panorama shrunk from {}x{} to {}x{} (the GPU's largest texture is {})",
                     source.width, source.height, panorama->width, panorama->height,
                     device.caps().max_texture_size);

    const bool hdr = panorama->format == assets::PixelFormat::RGBA32F;
    const int levels = mip_count(panorama->width);
    gpu::Texture source_texture =
        device.create_texture({.label = "environment panorama",
                               .format = hdr ? gpu::TextureFormat::RGBA16F : gpu::TextureFormat::SRGB8_A8,
                               .width = panorama->width,
                               .height = panorama->height,
                               .mip_levels = levels});
    source_texture.upload(std::as_bytes(std::span(panorama->data)));
    if (hdr) {
        // Half floats filter everywhere in GLES 3.0, but the GPU makes their mipmaps only where it can
        // render into them: average the linear radiance here instead.
        assets::Image level_image = *panorama;
        for (int level = 1; level < levels; ++level) {
            level_image = assets::halve(level_image);
            source_texture.upload(std::as_bytes(std::span(level_image.data)), level);
        }
    } else {
        source_texture.generate_mipmaps();
    }
    gpu::Sampler sampler =
        device.create_sampler({.label = "environment panorama", .mipmaps = true, .wrap = gpu::Wrap::Repeat});

    std::vector<std::string> defines;
    if (rgbm) defines.emplace_back("OUTPUT_RGBM");
    auto pipeline = device.create_pipeline({.label = "equirect to cube",
                                            .fragment = "equirect_to_cube.frag",
                                            .defines = defines,
                                            .textures = {"u_panorama"}});
    if (!pipeline) return pipeline.error();

    gpu::Texture cube = device.create_texture({.label = "environment",
                                               .kind = gpu::TextureKind::Cube,
                                               .format = format,
                                               .width = face_size,
                                               .height = face_size,
                                               .mip_levels = mip_count(face_size)});
    // Every level from the panorama itself, filtered as wide as its texels: RGBM texels cannot be averaged
    // by the driver's mipmap generation (a bright window next to a dark wall would lose most of its light).
    for (int level = 0; level < cube.desc().mip_levels; ++level) {
        const int size = std::max(1, face_size >> level);
        for (int face = 0; face < 6; ++face) {
            auto pass = device.begin_pass(
                {.label = "equirect to cube",
                 .target = {.texture = &cube, .size = {size, size}, .face = face, .level = level},
                 .load = gpu::LoadOp::DontCare});
            pass.set_pipeline(*pipeline)
                .set_texture(0, source_texture, sampler)
                .set("u_face", face)
                .set("u_face_size", static_cast<float>(size))
                .set("u_panorama_size", glm::vec2(panorama->width, panorama->height))
                .set("u_max_lod", static_cast<float>(levels - 1));
            pass.draw_fullscreen();
        }
    }
    return cube;
}

}  // namespace puddle::systems
