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

Result<gpu::Texture> create_environment_cube(gpu::Device& device, gpu::TextureFormat format, int face_size,
                                             int smallest_face_size) {
    auto make = [&](int size) {
        return device.create_texture({.label = "environment",
                                      .kind = gpu::TextureKind::Cube,
                                      .format = format,
                                      .width = size,
                                      .height = size,
                                      .mip_levels = mip_count(size),
                                      .render_target = true});
    };
    auto cube = make(face_size);
    if (cube || cube.error().code != ExitCode::GpuMemory) return cube;
    const Error first = cube.error();
    int size = face_size;
    while (size / 2 >= std::max(smallest_face_size, 1)) {
        size /= 2;
        auto smaller = make(size);
        if (smaller) {
            spdlog::warn("{}; using {}x{} faces instead", first.message, size, size);
            return smaller;
        }
        if (smaller.error().code != ExitCode::GpuMemory) return smaller;
    }
    if (size == face_size) return first;
    return Error{fmt::format("{}; faces down to {}x{} did not fit either", first.message, size, size),
                 first.code};
}

int auto_face_size(int panorama_width, int max_cube_size) {
    return std::clamp(panorama_width / 4, 1, std::min(1024, max_cube_size));
}

Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& source, int face_size,
                                      gpu::TextureFormat format, bool rgbm, int smallest_face_size) {
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
    auto made_source =
        device.create_texture({.label = "environment panorama",
                               .format = hdr ? gpu::TextureFormat::RGBA16F : gpu::TextureFormat::SRGB8_A8,
                               .width = panorama->width,
                               .height = panorama->height,
                               .mip_levels = levels});
    if (!made_source) return made_source.error();
    gpu::Texture source_texture = std::move(made_source).value();
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

    auto made_cube = create_environment_cube(device, format, face_size, smallest_face_size);
    if (!made_cube) return made_cube.error();
    gpu::Texture cube = std::move(made_cube).value();
    face_size = cube.width();
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
