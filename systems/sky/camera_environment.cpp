#include "systems/sky/camera_environment.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <thread>

#include "camera/frame_layout.hpp"
#include "camera/yuv_matrix.hpp"
#include "render/view_basis.hpp"

namespace puddle::systems {

using camera::PixelLayout;
using params::ParamId;

namespace {

// Makes `texture` anew only when its shape changes: once per stream, never per frame. A texture the GPU
// cannot make disables the camera environment (one error line; the cubemap stays).
Result<void> ensure_texture(gpu::Device& device, gpu::Texture& texture, const gpu::TextureDesc& desc,
                            CameraEnvironment& env) {
    if (texture && texture.width() == desc.width && texture.height() == desc.height &&
        texture.desc().format == desc.format && texture.desc().mip_levels == desc.mip_levels)
        return {};
    auto made = device.create_texture(desc);
    if (!made) {
        env.setup = CameraSetup::failed;
        return made.error();
    }
    texture = std::move(made).value();
    return {};
}

Result<void> ensure_colour(gpu::Device& device, CameraEnvironment& env, int width, int height) {
    return ensure_texture(device, env.colour,
                          {.label = "camera colour",
                           .format = gpu::TextureFormat::SRGB8_A8,
                           .width = width,
                           .height = height,
                           .mip_levels = gpu::full_mip_count(std::max(width, height)),
                           .render_target = true},
                          env);
}

const gpu::ExternalImage* import_buffer(gpu::Device& device, const camera::CameraImage& image,
                                        const camera::FrameLayout& layout, CameraEnvironment& env) {
    const auto index = static_cast<std::size_t>(image.buffer_index);
    if (index >= env.imported.size()) env.imported.resize(index + 1);  // once per driver buffer
    gpu::ExternalImage& cached = env.imported[index];
    if (!cached) {
        const bool nv12 = image.layout == PixelLayout::Nv12;
        const auto pitch = static_cast<std::uint32_t>(image.stride);
        auto made = device.create_external_image(
            {.label = "camera buffer",
             .format = nv12 ? gpu::DmabufFormat::Nv12 : gpu::DmabufFormat::Yuyv,
             .width = image.width,
             .height = image.height,
             .planes = {{.fd = image.dmabuf_fd, .offset = 0, .pitch = pitch},
                        {.fd = nv12 ? image.dmabuf_fd : -1,
                         .offset = static_cast<std::uint32_t>(layout.planes[1].offset),
                         .pitch = pitch}},
             .bt709 = image.matrix == camera::YuvMatrix::Bt709,
             .full_range = image.full_range});
        if (!made) {
            spdlog::warn("{}; copying camera frames instead", made.error().message);
            env.zero_copy = false;
            return nullptr;
        }
        cached = std::move(made).value();
    }
    return &cached;
}

gpu::PipelineDesc camera_pass_desc(CameraPass pass) {
    const std::vector<std::string> planes{"u_plane0", "u_plane1"}, cube{"u_env", "u_camera"};
    switch (pass) {
        case CameraPass::convert_yuyv:
            return {.label = "camera convert (YUYV)",
                    .fragment = "camera_convert.frag",
                    .defines = {"LAYOUT_YUYV"},
                    .textures = planes};
        case CameraPass::convert_nv12:
            return {.label = "camera convert (NV12)",
                    .fragment = "camera_convert.frag",
                    .defines = {"LAYOUT_NV12"},
                    .textures = planes};
        case CameraPass::convert_external:
            return {.label = "camera convert (external)",
                    .fragment = "camera_convert.frag",
                    .defines = {"EXTERNAL_OES"},
                    .textures = {"u_external"}};
        case CameraPass::cube_planar:
            return {.label = "camera cube (planar)", .fragment = "camera_cube.frag", .textures = cube};
        case CameraPass::cube_mirror_ball:
            return {.label = "camera cube (mirror ball)",
                    .fragment = "camera_cube.frag",
                    .defines = {"MAPPING_MIRROR_BALL"},
                    .textures = cube};
    }
    return {};
}

constexpr std::array all_camera_passes{CameraPass::convert_yuyv, CameraPass::convert_nv12,
                                       CameraPass::convert_external, CameraPass::cube_planar,
                                       CameraPass::cube_mirror_ball};

// Every pass's pipeline is built before `ready`, so this is never null where the system draws.
const render::BuiltPipeline& built(const CameraEnvironment& env, CameraPass pass) {
    return *env.pipelines.find(pass);
}

// Everything but the pipelines and the cube (made at the first frame, for the sky then shown): samplers.
void finish_camera_resources(gpu::Device& device, CameraEnvironment& env) {
    env.nearest = device.create_sampler(
        {.label = "camera planes", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
    env.linear = device.create_sampler({.label = "camera colour", .mipmaps = true});
}

// The cube at the size the sky asks for: made at the first frame, made again when a reloaded sky's face
// size changes it (not per frame).
Result<void> ensure_cube(gpu::Device& device, const Environment& sky, CameraEnvironment& env) {
    const int size = camera_cube_size(sky);
    return ensure_texture(device, env.cube,
                          {.label = "camera environment",
                           .kind = gpu::TextureKind::Cube,
                           .format = gpu::TextureFormat::SRGB8_A8,
                           .width = size,
                           .height = size,
                           .mip_levels = gpu::full_mip_count(size),
                           .render_target = true},
                          env);
}

}  // namespace

int camera_cube_size(const Environment& sky) {
    return sky.cube ? std::clamp(sky.cube.width(), 1, camera_cube_max_size) : camera_cube_max_size;
}

std::optional<Result<void>> poll_camera_pipelines(gpu::Device& device, CameraEnvironment& env) {
    if (env.ready()) return Result<void>{};
    if (env.setup == CameraSetup::unprobed) {
        env.support = device.external_image_support();
        env.zero_copy = env.support.dmabuf_import;
        env.setup = CameraSetup::building;
    }
    bool waiting = false;
    for (const CameraPass pass : all_camera_passes) {
        if (pass == CameraPass::convert_external && !env.support.external_sampler) continue;
        auto polled = env.pipelines.poll(device, pass, [pass] { return camera_pass_desc(pass); });
        if (!polled) return Result<void>(polled.error());
        if (!*polled) waiting = true;
    }
    if (waiting) return std::nullopt;
    finish_camera_resources(device, env);
    if (!env.failed()) env.setup = CameraSetup::ready;
    return Result<void>{};
}

Result<void> build_camera_pipelines(gpu::Device& device, CameraEnvironment& env) {
    for (;;) {
        if (auto done = poll_camera_pipelines(device, env)) return *done;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

Result<void> upload_camera_frame(gpu::Device& device, const camera::CameraImage& image,
                                 CameraEnvironment& env) {
    if (env.failed()) return {};
    // Built off the frame thread (Device::request_pipeline): until they are ready the frame is skipped and
    // the puddle keeps reflecting the cubemap.
    auto ready = poll_camera_pipelines(device, env);
    if (!ready) return {};
    if (!*ready) {
        env.setup = CameraSetup::failed;
        return *ready;
    }
    // Checked before anything changes: a frame that does not fit its format is not uploaded (and the
    // colour texture keeps the previous one). The capture drops such frames already; this guards the
    // GPU, which would read past the end.
    auto layout = camera::frame_layout(image.layout, image.width, image.height, image.stride);
    if (!layout)
        return make_error(ExitCode::Runtime, "camera: frame not uploaded: {}", layout.error().message);
    if (image.data.size() < layout->bytes)
        return make_error(ExitCode::Runtime, "camera: frame not uploaded: {} {}x{} in {} bytes, needs {}",
                          camera::layout_name(image.layout), image.width, image.height, image.data.size(),
                          layout->bytes);
    for (int i = 0; i < layout->count; ++i) {
        const camera::PlaneLayout& p = layout->planes[static_cast<std::size_t>(i)];
        if (p.stride % p.texel_bytes != 0)  // GL counts row lengths in whole texels
            return make_error(ExitCode::Runtime,
                              "camera: frame not uploaded: {} bytesperline {} is not a whole number of "
                              "{}-byte texels",
                              camera::layout_name(image.layout), p.stride, p.texel_bytes);
    }
    env.pending = image;
    env.pending.data = {};
    env.layout = image.layout;
    env.pending_import = nullptr;
    if (auto r = ensure_colour(device, env, image.width, image.height); !r) return r;
    if (image.layout == PixelLayout::Rgba) {
        env.colour.upload_rows(image.data, image.stride);
        env.colour.generate_mipmaps();
        env.frame = CameraFrame::converted;
        return {};
    }
    if (env.zero_copy && image.dmabuf_fd >= 0 && env.support.external_sampler)
        env.pending_import = import_buffer(device, image, *layout, env);
    if (!env.pending_import) {
        // YUYV: one RGBA8 texel per pixel pair. NV12: R8 luma, then RG8 chroma at ceil(w/2) x ceil(h/2).
        const bool yuyv = image.layout == PixelLayout::Yuyv;
        const std::array<gpu::TextureFormat, 2> formats{
            yuyv ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::R8, gpu::TextureFormat::RG8};
        const std::array<const char*, 2> labels{"camera plane 0", "camera plane 1 (UV)"};
        const std::array<gpu::Texture*, 2> planes{&env.plane0, &env.plane1};
        for (std::size_t i = 0; i < static_cast<std::size_t>(layout->count); ++i) {
            const camera::PlaneLayout& p = layout->planes[i];
            if (auto r = ensure_texture(
                    device, *planes[i],
                    {.label = labels[i], .format = formats[i], .width = p.texels, .height = p.rows}, env);
                !r)
                return r;
            planes[i]->upload_rows(image.data.subspan(p.offset), p.stride);
        }
    }
    env.frame = CameraFrame::uploaded;
    return {};
}

void drop_camera_frames(CameraEnvironment& env) {
    env.frame = CameraFrame::none;
    env.pending_import = nullptr;
    env.imported.clear();  // the buffers they were made from are gone
}

void camera_environment_system(gpu::Device& device, const params::Params& params, const Environment& sky,
                               CameraEnvironment& env) {
    if (!env.ready()) return;
    if (env.frame == CameraFrame::uploaded) {
        const camera::YuvToRgb m = camera::yuv_to_rgb(env.pending.matrix, env.pending.full_range);
        auto pass = device.begin_pass(
            {.label = "camera convert",
             .target = {.texture = &env.colour, .size = {env.colour.width(), env.colour.height()}},
             .load = gpu::LoadOp::DontCare});  // the conversion writes every texel
        if (env.pending_import) {
            pass.set_pipeline(built(env, CameraPass::convert_external).pipeline)
                .set_texture(0, env.pending_import->texture(), env.linear)
                .set("u_size", glm::vec2(env.colour.width(), env.colour.height()));
        } else {
            const bool yuyv = env.layout == PixelLayout::Yuyv;
            pass.set_pipeline(built(env, yuyv ? CameraPass::convert_yuyv : CameraPass::convert_nv12).pipeline)
                .set_texture(0, env.plane0, env.nearest)
                .set_texture(1, yuyv ? env.plane0 : env.plane1, env.nearest)
                .set("u_yuv_matrix", m.matrix)
                .set("u_yuv_offset", m.offset);
        }
        pass.draw_fullscreen();
        pass.end();
        env.colour.generate_mipmaps();
        env.frame = CameraFrame::converted;
    }
    if (env.frame == CameraFrame::none) return;
    const bool resized = env.cube && env.cube.width() != camera_cube_size(sky);
    if (env.frame == CameraFrame::cube_drawn && !resized && env.cube_params_revision == params.revision())
        return;
    env.frame = CameraFrame::cube_drawn;
    if (auto made = ensure_cube(device, sky, env); !made) {  // ensure_texture has set `failed`
        spdlog::error("camera: {} (the cubemap stays)", made.error().message);
        return;
    }
    env.cube_params_revision = params.revision();

    // The image centre looks toward -X, 35 degrees up: where the default view's reflection looks.
    const bool ball = params.get<ParamId::environment_camera_mapping>() == params::CameraMapping::mirror_ball;
    const float aspect =
        static_cast<float>(env.colour.width()) / static_cast<float>(std::max(env.colour.height(), 1));
    const render::ViewBasis view = render::view_basis(glm::vec3(0), glm::vec3(-1.0f, 0.7f, 0.0f),
                                                      params.get<ParamId::environment_camera_fov>(), aspect);
    const render::BuiltPipeline& cube =
        built(env, ball ? CameraPass::cube_mirror_ball : CameraPass::cube_planar);
    for (int face = 0; face < 6; ++face) {
        auto pass = device.begin_pass(
            {.label = "camera cube face",
             .target = {.texture = &env.cube, .size = {env.cube.width(), env.cube.width()}, .face = face},
             .load = gpu::LoadOp::DontCare});  // each face is drawn whole
        pass.set_pipeline(cube.pipeline)
            .set_texture(0, sky.cube, sky.sampler)
            .set_texture(1, env.colour, env.linear)
            .set("u_env_rgbm", sky.rgbm ? 1 : 0)
            .set("u_face", face)
            .set("u_axis", view.forward)
            .set("u_right", view.right)
            .set("u_up", view.up)
            .set("u_aspect", aspect)
            .set("u_tan_half_fov", view.scale.y);
        render::set_param_uniforms(pass, cube.params, params);
        pass.draw_fullscreen();
    }
    env.cube.generate_mipmaps();
}

}  // namespace puddle::systems
