#include "systems/environment_system.hpp"

#include <spdlog/spdlog.h>

#include <bit>
#include <cstddef>
#include <span>

#include "assets/environment_images.hpp"
#include "assets/image_io.hpp"
#include "assets/procedural_ground.hpp"
#include "assets/rgbm.hpp"
#include "systems/equirect_to_cube.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

int mip_count(int size) {
    return std::bit_width(static_cast<unsigned>(std::max(size, 1)));
}

struct CubeFormat {
    gpu::TextureFormat format;
    bool rgbm;
};

// HDR wants half floats; their mipmaps need half-float render targets, so without those it is RGBM in RGBA8.
CubeFormat cube_format(const gpu::Capabilities& caps, bool hdr) {
    if (!hdr) return {gpu::TextureFormat::SRGB8_A8, false};
    if (caps.half_float_render_targets) return {gpu::TextureFormat::RGBA16F, false};
    return {gpu::TextureFormat::RGBA8, true};
}

Result<gpu::Texture> upload_faces(gpu::Device& device, assets::CubeImages& cube, CubeFormat f,
                                  int smallest_face_size) {
    while (cube.faces[0].width > device.caps().max_cube_map_size)
        for (assets::Image& face : cube.faces) face = assets::halve(face);
    auto made = create_environment_cube(device, f.format, cube.faces[0].width,
                                        std::min(smallest_face_size, cube.faces[0].width));
    if (!made) return made.error();
    gpu::Texture texture = std::move(made).value();
    while (cube.faces[0].width > texture.width())  // it fitted only smaller
        for (assets::Image& face : cube.faces) face = assets::halve(face);
    for (std::size_t face = 0; face < 6; ++face) {
        if (!f.rgbm) {
            texture.upload(std::as_bytes(std::span(cube.faces[face].data)), 0, static_cast<int>(face));
            continue;
        }
        // RGBM texels cannot be averaged by glGenerateMipmap: each level from linear averages here.
        assets::Image level_image = cube.faces[face];
        for (int level = 0; level < texture.desc().mip_levels; ++level) {
            if (level > 0) level_image = assets::halve(level_image);
            const assets::Image encoded = assets::encode_rgbm(level_image);
            texture.upload(std::as_bytes(std::span(encoded.data)), level, static_cast<int>(face));
        }
    }
    if (!f.rgbm) texture.generate_mipmaps();
    return texture;
}

// A live reload that does not fit in GPU memory halves the face size down to a floor: at start-up there is
// none (the size asked for fails with exit code 5), a new image stops at 256, and the image shown now stops
// above its current size (a smaller copy of the same sky gains nothing: the one shown stays).
int smallest_face_size(const Environment& shown, const params::Params& params, int asked) {
    constexpr int fallback_floor = 256;
    if (!shown.cube) return asked;
    if (shown.requested_image == params.s(ParamId::environment_image))
        return std::min(asked, shown.cube.width() * 2);
    return std::min(asked, fallback_floor);
}

}  // namespace

Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env) {
    auto images = assets::load_environment_images(params.s(ParamId::environment_image));
    if (!images) return images.error();
    const CubeFormat f = cube_format(device.caps(), images->hdr());

    Environment e;
    e.source = images->source;
    e.hdr = images->hdr();
    e.rgbm = f.rgbm;
    if (images->faces) {
        auto cube = upload_faces(device, *images->faces, f,
                                 smallest_face_size(env, params, images->faces->faces[0].width));
        if (!cube) return cube.error();
        e.cube = std::move(cube).value();
    } else {
        const int asked = params.i(ParamId::environment_face_size);
        const int max_size = device.caps().max_cube_map_size;
        if (asked > max_size)
            spdlog::warn("environment.face_size: {} is more than this GPU's largest cube map; using {}",
                         asked, max_size);
        const int size =
            asked > 0 ? std::min(asked, max_size) : auto_face_size(images->panorama.width, max_size);
        auto cube = equirect_to_cube(device, images->panorama, size, f.format, f.rgbm,
                                     smallest_face_size(env, params, size));
        if (!cube) return cube.error();
        e.cube = std::move(cube).value();
    }
    e.sampler = device.create_sampler({.label = "environment", .mipmaps = true, .wrap = gpu::Wrap::Clamp});
    spdlog::info(
        "environment: {} ({}x{} faces, {})", e.source, e.cube.width(), e.cube.height(),
        e.rgbm ? "HDR as RGBM8 (no half-float render targets)" : gpu::format_name(e.cube.desc().format));
    e.requested_image = params.s(ParamId::environment_image);
    e.requested_face_size = params.i(ParamId::environment_face_size);
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
        // An HDR file is stored as sRGB like any other: the ground is lit, never a light.
        auto loaded = assets::read_color_image(path);
        if (!loaded) return loaded.error();
        image = assets::to_srgb8(*loaded);
        g.source = path;
    }
    while (std::max(image.width, image.height) > device.caps().max_texture_size) image = assets::halve(image);
    auto texture = device.create_texture({.label = "ground",
                                          .format = gpu::TextureFormat::SRGB8_A8,
                                          .width = image.width,
                                          .height = image.height,
                                          .mip_levels = mip_count(std::max(image.width, image.height))});
    if (!texture) return texture.error();
    g.texture = std::move(texture).value();
    g.texture.upload(std::as_bytes(std::span(image.data)));
    g.texture.generate_mipmaps();
    // Trilinear and anisotropic (where the GPU has it): tiled paving at grazing angles does not shimmer.
    g.sampler = device.create_sampler(
        {.label = "ground", .mipmaps = true, .wrap = gpu::Wrap::Repeat, .anisotropy = 8.0f});
    g.requested_image = path;
    ground = std::move(g);
    return {};
}

void environment_reload_system(ecs::World& world) {
    const params::Params& params = world.resource<params::Params>();
    auto& device = world.resource<gpu::Device>();
    auto& env = world.resource<Environment>();
    if (params.s(ParamId::environment_image) != env.requested_image ||
        params.i(ParamId::environment_face_size) != env.requested_face_size) {
        if (auto r = load_environment(device, params, env); !r) {
            spdlog::error("{} (keeping {})", r.error().message, env.source);
            env.requested_image = params.s(ParamId::environment_image);
            env.requested_face_size = params.i(ParamId::environment_face_size);
        }
    }
    auto& ground = world.resource<Ground>();
    if (params.s(ParamId::ground_image) != ground.requested_image) {
        if (auto r = load_ground(device, params, ground); !r) {
            spdlog::error("{} (keeping {})", r.error().message, ground.source);
            ground.requested_image = params.s(ParamId::ground_image);
        }
    }
}

}  // namespace puddle::systems
