#include "systems/sky/environment_system.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstddef>
#include <span>

#include "assets/image_io.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

Result<void> upload_ground(gpu::Device& device, PreparedGround prepared, const std::string& path,
                           Ground& ground) {
    const assets::Image& image = prepared.image;
    Ground g;
    g.source = std::move(prepared.source);
    auto texture =
        device.create_texture({.label = "ground",
                               .format = gpu::TextureFormat::SRGB8_A8,
                               .width = image.width,
                               .height = image.height,
                               .mip_levels = gpu::full_mip_count(std::max(image.width, image.height))});
    if (!texture) return texture.error();
    g.texture = std::move(texture).value();
    g.texture.upload(std::as_bytes(std::span(image.data)));
    g.texture.generate_mipmaps();
    // Trilinear and anisotropic (where the GPU has it): a tiled image at grazing angles does not shimmer.
    g.sampler = device.create_sampler(
        {.label = "ground", .mipmaps = true, .wrap = gpu::Wrap::Repeat, .anisotropy = 8.0f});
    g.requested_image = path;
    g.made = true;
    ground = std::move(g);
    return {};
}

// What shows while no image is: the checkerboard or the paving, both drawn by the shader.
std::string drawn_ground(const params::Params& params) {
    if (!params.get<ParamId::ground_checkerboard>()) return "procedural setts (drawn by the shader)";
    if (params.get<ParamId::ground_image>().empty()) return "checkerboard";
    return "checkerboard (ground.image is read when ground.checkerboard turns false)";
}

Result<void> placeholder_ground(gpu::Device& device, const params::Params& params, Ground& ground) {
    Ground g;
    g.source = drawn_ground(params);
    auto texture = device.create_texture(
        {.label = "ground placeholder", .format = gpu::TextureFormat::SRGB8_A8, .width = 1, .height = 1});
    if (!texture) return texture.error();
    g.texture = std::move(texture).value();
    const std::uint8_t grey[4] = {128, 128, 128, 255};
    g.texture.upload(std::as_bytes(std::span(grey)));
    g.sampler = device.create_sampler({.label = "ground placeholder"});
    ground = std::move(g);
    return {};
}

// A live reload that does not fit in GPU memory halves the face size down to a floor: at start-up there is
// none (the size asked for fails with exit code 5), a new image stops at 256, and the image shown now stops
// above its current size (a smaller copy of the same sky gains nothing: the one shown stays).
int fallback_floor(const Environment& shown, const params::Params& params) {
    constexpr int new_image_floor = 256;
    if (!shown.cube) return EnvironmentBuild::no_fallback;
    if (shown.requested_image == params.get<ParamId::environment_image>()) return shown.cube.width() * 2;
    return new_image_floor;
}

// A new sky asked for: decoded on the worker; the old one stays on screen meanwhile.
void start_environment_reload(const gpu::Device& device, const params::Params& params, Environment& env,
                              EnvironmentReload& reload) {
    reload.fallback_floor = fallback_floor(env, params);
    env.requested_image = params.get<ParamId::environment_image>();
    env.requested_face_size = params.get<ParamId::environment_face_size>();
    reload.environment_build.reset();  // a half-built older one is dropped
    const EnvironmentRequest request = EnvironmentRequest::from(params, device.caps());
    reload.environment.submit([request](std::stop_token stop) { return prepare_environment(request, stop); });
    spdlog::info("environment: loading {} (showing {} until it is ready)",
                 request.image.empty() ? "the procedural night sky" : request.image, env.source);
}

void continue_environment_reload(gpu::Device& device, Environment& env, EnvironmentReload& reload) {
    if (auto prepared = reload.environment.take()) {
        if (!*prepared) {
            spdlog::error("{} (keeping {})", prepared->error().message, env.source);
            return;
        }
        reload.environment_build.emplace(std::move(prepared->value()), reload.fallback_floor);
    }
    if (!reload.environment_build) return;
    auto done = reload.environment_build->step(device, env.panorama_pipelines);
    if (!done) {
        spdlog::error("{} (keeping {})", done.error().message, env.source);
        reload.environment_build.reset();
    } else if (*done) {
        reload.environment_build->finish(device, env);
        reload.environment_build.reset();
    }
}

}  // namespace

Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env) {
    auto prepared = prepare_environment(EnvironmentRequest::from(params, device.caps()));
    if (!prepared) return prepared.error();
    EnvironmentBuild build(std::move(prepared).value(), fallback_floor(env, params));
    for (;;) {
        auto done = build.step(device, env.panorama_pipelines);
        if (!done) return done.error();
        if (*done) break;
    }
    Environment e;
    e.panorama_pipelines = std::move(env.panorama_pipelines);
    build.finish(device, e);
    e.requested_image = params.get<ParamId::environment_image>();
    e.requested_face_size = params.get<ParamId::environment_face_size>();
    env = std::move(e);
    return {};
}

Result<PreparedGround> prepare_ground(const std::string& path, int max_texture_size) {
    PreparedGround g;
    // An HDR file is stored as sRGB like any other: the ground is lit, never a light.
    auto loaded = assets::read_color_image(path);
    if (!loaded) return Error{"ground.image: " + loaded.error().message, loaded.error().code};
    g.image = assets::to_srgb8(*loaded);
    g.source = path;
    const int width = g.image.width, height = g.image.height;
    const int max_side = std::min(max_texture_size, ground_max_size);
    while (std::max(g.image.width, g.image.height) > max_side) g.image = assets::halve(g.image);
    if (g.image.width != width)
        g.source =
            fmt::format("{} ({}x{}, halved from {}x{})", path, g.image.width, g.image.height, width, height);
    return g;
}

Result<void> load_ground(gpu::Device& device, const params::Params& params, Ground& ground) {
    const std::string& path = params.get<ParamId::ground_image>();
    if (params.get<ParamId::ground_checkerboard>() || path.empty())
        return placeholder_ground(device, params, ground);
    auto prepared = prepare_ground(path, device.caps().max_texture_size);
    if (!prepared) return prepared.error();
    return upload_ground(device, std::move(prepared).value(), path, ground);
}

void environment_reload_system(gpu::Device& device, const params::Params& params, Environment& env,
                               Ground& ground, EnvironmentReload& reload) {
    if (params.get<ParamId::environment_image>() != env.requested_image ||
        params.get<ParamId::environment_face_size>() != env.requested_face_size)
        start_environment_reload(device, params, env, reload);
    continue_environment_reload(device, env, reload);

    // An image is asked for only while it shows (Ground): a new ground.image under the checkerboard waits.
    // One taken away is forgotten, so asking for the same file again reads it again (it may be fixed now).
    const std::string& path = params.get<ParamId::ground_image>();
    if (path.empty() && ground.requested_image) {
        ground.requested_image.reset();
        if (ground.made)  // frees the image's memory
            if (auto r = placeholder_ground(device, params, ground); !r)
                spdlog::error("{}", r.error().message);
        spdlog::info("ground: {}", drawn_ground(params));
    }
    const bool shown = !params.get<ParamId::ground_checkerboard>() && !path.empty();
    if (shown && ground.requested_image != path) {
        ground.requested_image = path;
        const int max_size = device.caps().max_texture_size;
        reload.ground.submit([path = *ground.requested_image, max_size](std::stop_token) {
            return prepare_ground(path, max_size);
        });
    }
    if (auto prepared = reload.ground.take(); prepared && ground.requested_image) {  // else taken away
        const std::string keeping = params.get<ParamId::ground_checkerboard>() ? "the checkerboard"
                                    : ground.made                              ? ground.source
                                                                               : "the procedural setts";
        if (!*prepared)
            spdlog::error("{} (keeping {})", prepared->error().message, keeping);
        else if (auto r =
                     upload_ground(device, std::move(prepared->value()), *ground.requested_image, ground);
                 !r)
            spdlog::error("{} (keeping {})", r.error().message, keeping);
        else
            spdlog::info("ground: {}", ground.source);
    }
}

}  // namespace puddle::systems
