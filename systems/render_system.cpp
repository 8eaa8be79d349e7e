#include "systems/render_system.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <glm/mat3x3.hpp>

#include "render/param_uniforms.hpp"
#include "render/view_basis.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

gpu::PipelineDesc puddle_desc(const render::PuddleVariant& v, bool surface_unorm) {
    return {.label = "puddle",
            .vertex = "view_window.vert",
            .fragment = "puddle.frag",
            .defines = render::variant_defines(v, surface_unorm),
            .textures = {"u_surface", "u_env", "u_ground"}};
}

}  // namespace

const render::BuiltPipeline* PuddleRenderer::pipeline(gpu::Device& device, const render::PuddleVariant& v) {
    const bool was_ready = variants.find(v) != nullptr;
    const render::BuiltPipeline* p =
        variants.request_or_last(device, v, [&] { return puddle_desc(v, surface_unorm); });
    if (!was_ready && variants.find(v))
        spdlog::debug("render: compiled the puddle shader for {}", render::describe(v));
    return p;
}

Result<void> build_puddle_renderer(gpu::Device& device, const Surface& surface, const Environment& env,
                                   const params::Params& params, PuddleRenderer& renderer) {
    renderer = PuddleRenderer{};
    renderer.surface_unorm = surface.unorm;
    const render::PuddleVariant v = render::choose_puddle_variant(params, env.rgbm);
    return renderer.variants.ensure(device, v, [&] { return puddle_desc(v, surface.unorm); });
}

void puddle_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, PuddleRenderer& renderer,
                   const RenderTarget& target, const CameraEnvironment& camera) {
    render_system(device, params, surface, env, ground, renderer, target, camera.reflection());
}

void render_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, PuddleRenderer& renderer,
                   const RenderTarget& target, const gpu::Texture* environment_override,
                   const render::PuddleVariant* variant) {
    const gpu::FrameTarget& frame = target.target;
    const bool rgbm = env.rgbm && !environment_override;  // the camera cube is sRGB8
    render::PuddleVariant chosen = variant ? *variant : render::choose_puddle_variant(params, rgbm);
    // The setts show until the first image asked for is made (Ground).
    if (!variant && chosen.ground == render::GroundKind::Image && !ground.made)
        chosen.ground = render::GroundKind::Paving;
    const render::BuiltPipeline* pipeline = renderer.pipeline(device, chosen);
    if (!pipeline) return;

    // Everything uniform across the screen is worked out here once, not per pixel. The camera is the whole
    // view's: a tile of a wall shows its part of that frustum.
    const render::ViewBasis cam =
        render::view_basis(params.get<ParamId::camera_position>(), params.get<ParamId::camera_target>(),
                           params.get<ParamId::camera_fov>(), target.view.view_aspect(frame.size));
    const float a = params.get<ParamId::environment_rotation>();
    // Column-major rotation about +Y.
    const glm::mat3 env_matrix(std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a));

    auto pass = device.begin_pass({.label = "puddle", .target = frame, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(pipeline->pipeline)
        .set_texture(0, surface.texture, surface.sampler)
        .set_texture(1, environment_override ? *environment_override : env.cube, env.sampler)
        .set_texture(2, ground.texture, ground.sampler);
    render::set_param_uniforms(pass, pipeline->params, params);
    pass.set("u_view_window", target.view.uniform())
        .set("u_cam_forward", cam.forward)
        .set("u_cam_right", cam.right)
        .set("u_cam_up", cam.up)
        .set("u_cam_scale", cam.scale)
        .set("u_env_matrix", env_matrix)
        .set("u_env_scale", std::exp2(params.get<ParamId::environment_exposure>()))
        .set("u_slope_scale",
             static_cast<float>(surface.resolution) * 0.5f /
                 glm::vec2(params.get<ParamId::puddle_size>().x, params.get<ParamId::puddle_size>().z));
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
