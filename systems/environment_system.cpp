#include "systems/environment_system.hpp"

#include <bit>
#include <cstddef>
#include <filesystem>

#include "assets/cubemap_loader.hpp"
#include "assets/image_io.hpp"
#include "assets/procedural.hpp"
#include "assets/procedural_ground.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

int mip_count(int size) { return std::bit_width(static_cast<unsigned>(std::max(size, 1))); }

Result<assets::CubeImages> cube_images(const std::string& spec) {
    if (spec.empty()) return assets::night_sky_cubemap(256);
    if (spec.find('|') == std::string::npos) return assets::load_cubemap_folder(spec);
    std::array<std::string, 6> paths;
    std::size_t start = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        const std::size_t bar = spec.find('|', start);
        if ((i < 5) == (bar == std::string::npos))
            return make_error(ExitCode::Asset,
                              "environment.image: expected a folder or six paths (px, nx, py, ny, pz, nz), got '{}'",
                              spec);
        paths[i] = spec.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
        start = bar + 1;
    }
    return assets::load_cubemap_faces(paths);
}

}  // namespace

Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env) {
    auto images = cube_images(params.s(ParamId::environment_image));
    if (!images) return images.error();
    const int size = images->faces[0].width;
    Environment e;
    e.source = images->source;
    e.cube = device.create_texture({.label = "environment",
                                    .kind = gpu::TextureKind::Cube,
                                    .format = gpu::TextureFormat::SRGB8_A8,
                                    .width = size,
                                    .height = size,
                                    .mip_levels = mip_count(size)});
    for (int face = 0; face < 6; ++face)
        e.cube.upload(std::as_bytes(std::span(images->faces[static_cast<std::size_t>(face)].data)), 0, face);
    e.cube.generate_mipmaps();
    e.sampler = device.create_sampler({.label = "environment", .mipmaps = true, .wrap = gpu::Wrap::Clamp});
    env = std::move(e);
    return {};
}

Result<void> load_ground(gpu::Device& device, const params::Params& params, Ground& ground) {
    const std::string& path = params.s(ParamId::ground_image);
    assets::Image image;
    Ground g;
    if (path.empty()) {
        image = assets::cobblestone_ground(512);
        g.source = "procedural cobblestones";
    } else {
        auto loaded = assets::read_image(path);
        if (!loaded) return loaded.error();
        image = std::move(loaded).value();
        g.source = path;
    }
    g.texture = device.create_texture({.label = "ground",
                                       .format = gpu::TextureFormat::SRGB8_A8,
                                       .width = image.width,
                                       .height = image.height,
                                       .mip_levels = mip_count(std::max(image.width, image.height))});
    g.texture.upload(std::as_bytes(std::span(image.data)));
    g.texture.generate_mipmaps();
    g.sampler = device.create_sampler({.label = "ground", .mipmaps = true, .wrap = gpu::Wrap::Repeat, .anisotropy = 8.0f});
    ground = std::move(g);
    return {};
}

}  // namespace puddle::systems
