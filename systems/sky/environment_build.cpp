#include "systems/sky/environment_build.hpp"

#include <spdlog/spdlog.h>

#include <cstddef>

#include "assets/environment_images.hpp"
#include "assets/rgbm.hpp"
#include "render/banded_upload.hpp"
#include "systems/sky/environment_system.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

Error stopped(const EnvironmentRequest& request) {
    return make_error(ExitCode::Asset, "environment: {}: loading stopped (a newer one was asked for)",
                      request.image);
}

// Six faces: shrunk to what the GPU takes; RGBM needs every level made here (its texels cannot be
// averaged by glGenerateMipmap), each from linear averages.
Result<void> prepare_faces(assets::CubeImages& cube, const EnvironmentRequest& request,
                           PreparedEnvironment& out, std::stop_token stop) {
    while (cube.faces[0].width > request.max_cube_map_size) {
        for (assets::Image& face : cube.faces) face = assets::halve(face);
        if (stop.stop_requested()) return stopped(request);
    }
    out.face_size = cube.faces[0].width;
    out.cube_levels.push_back(std::move(cube.faces));
    if (!out.rgbm) return {};
    const int levels = gpu::full_mip_count(out.face_size);
    for (int level = 1; level < levels; ++level) {
        std::array<assets::Image, 6> next;
        for (std::size_t face = 0; face < 6; ++face) next[face] = assets::halve(out.cube_levels.back()[face]);
        out.cube_levels.push_back(std::move(next));
        if (stop.stop_requested()) return stopped(request);
    }
    for (auto& level : out.cube_levels)
        for (assets::Image& face : level) face = assets::encode_rgbm(face);
    return {};
}

}  // namespace

EnvironmentRequest EnvironmentRequest::from(const params::Params& params, const gpu::Capabilities& caps) {
    return {.image = params.get<ParamId::environment_image>(),
            .face_size = params.get<ParamId::environment_face_size>(),
            .max_cube_map_size = caps.max_cube_map_size,
            .max_texture_size = caps.max_texture_size,
            .half_float_render_targets = caps.half_float_render_targets};
}

Result<PreparedEnvironment> prepare_environment(const EnvironmentRequest& request, std::stop_token stop) {
    // The procedural sky's clouds drift where the cube can hold where they may show (its alpha): not in
    // RGBM, whose alpha is the multiplier.
    const bool drifting_clouds = request.image.empty() && request.half_float_render_targets;
    auto images = assets::load_environment_images(
        request.image, request.face_size > 0 ? request.face_size : assets::procedural_sky_face_size,
        drifting_clouds ? assets::SkyClouds::drifting : assets::SkyClouds::baked);
    if (!images) return images.error();
    if (stop.stop_requested()) return stopped(request);
    PreparedEnvironment out;
    out.source = images->source;
    out.hdr = images->hdr();
    out.cloud_room = drifting_clouds;
    // HDR wants half floats; their mipmaps need half-float render targets, so without those it is RGBM
    // in RGBA8.
    out.rgbm = out.hdr && !request.half_float_render_targets;
    out.format = !out.hdr   ? gpu::TextureFormat::SRGB8_A8
                 : out.rgbm ? gpu::TextureFormat::RGBA8
                            : gpu::TextureFormat::RGBA16F;
    if (images->faces) {
        if (auto r = prepare_faces(*images->faces, request, out, stop); !r) return r.error();
        return out;
    }
    const int asked = request.face_size, max_size = request.max_cube_map_size;
    if (asked > max_size)
        spdlog::warn("environment.face_size: {} is more than this GPU's largest cube map; using {}", asked,
                     max_size);
    out.face_size =
        asked > 0 ? std::min(asked, max_size) : render::auto_face_size(images->panorama.width, max_size);
    out.panorama_levels =
        render::panorama_mip_chain(std::move(images->panorama), request.max_texture_size, stop);
    if (stop.stop_requested()) return stopped(request);
    return out;
}

EnvironmentBuild::EnvironmentBuild(PreparedEnvironment prepared, int fallback_floor)
    : prepared_(std::move(prepared)), smallest_face_size_(std::min(fallback_floor, prepared_.face_size)) {
    if (!prepared_.panorama_levels.empty())
        conversion_.emplace(std::move(prepared_.panorama_levels), prepared_.face_size, prepared_.format,
                            prepared_.rgbm, smallest_face_size_);
}

Result<bool> EnvironmentBuild::step(gpu::Device& device, render::EquirectPipelines& pipelines) {
    if (conversion_) {
        auto done = conversion_->step(device, texels_per_step, pipelines);
        if (done && *done) cube_ = conversion_->take_cube();
        return done;
    }
    if (!cube_) {
        auto made = render::create_environment_cube(device, prepared_.format, prepared_.face_size,
                                                    smallest_face_size_);
        if (!made) return made.error();
        cube_ = std::move(made).value();
        // It fitted only smaller: RGBM has every level made already, so the larger ones go; otherwise
        // level 0 is halved here (a fallback, once, rather than a frame-time cost of every reload).
        auto& levels = prepared_.cube_levels;
        while (levels.front()[0].width > cube_.width()) {
            if (levels.size() > 1) {
                levels.erase(levels.begin());
                continue;
            }
            for (assets::Image& face : levels.front()) face = assets::halve(face);
        }
        mipmaps_due_ = levels.size() == 1 && cube_.desc().mip_levels > 1;
        return false;  // a step of its own: the driver may clear a large texture's memory
    }
    if (level_ < prepared_.cube_levels.size()) {
        assets::Image& face = prepared_.cube_levels[level_][face_];
        if (!render::upload_next_band(cube_, face, static_cast<int>(level_), static_cast<int>(face_), row_,
                                      texels_per_step))
            return false;
        face = {};
        row_ = 0;
        if (++face_ == 6) face_ = 0, ++level_;
        return false;
    }
    if (mipmaps_due_) {
        cube_.generate_mipmaps();
        mipmaps_due_ = false;
    }
    return true;
}

void EnvironmentBuild::finish(gpu::Device& device, Environment& e) {
    e.cube = std::move(cube_);
    e.source = prepared_.source;
    e.hdr = prepared_.hdr;
    e.rgbm = prepared_.rgbm;
    e.cloud_room = prepared_.cloud_room;
    e.sampler = device.create_sampler({.label = "environment", .mipmaps = true, .wrap = gpu::Wrap::Clamp});
    spdlog::info(
        "environment: {} ({}x{} faces, {})", e.source, e.cube.width(), e.cube.height(),
        e.rgbm ? "HDR as RGBM8 (no half-float render targets)" : gpu::format_name(e.cube.desc().format));
}

}  // namespace puddle::systems
