#include "systems/puddle/render_system.hpp"

#include <spdlog/spdlog.h>

#include <cmath>
#include <glm/mat3x3.hpp>

#include "render/param_uniforms.hpp"
#include "render/view_basis.hpp"
#include "systems/water/capillary_step.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

gpu::PipelineDesc puddle_desc(const render::PuddleVariant& v, bool surface_unorm) {
    return {.label = "puddle",
            .vertex = "view_window.vert",
            .fragment = "puddle.frag",
            .defines = render::variant_defines(v, surface_unorm),
            .textures = {"u_surface", "u_env", "u_ground", "u_clouds"}};
}

}  // namespace

SurfaceMapping surface_mapping(const params::Params& params, const Surface& surface) {
    const float res = static_cast<float>(surface.resolution);
    const double res_d = surface.resolution;
    const bool tiled = surface_tiled(params);
    if (!tiled) {  // the reference: the field spans the puddle once, heights in wave.height_scale units
        const glm::vec2 size(params.get<ParamId::puddle_size>().x, params.get<ParamId::puddle_size>().z);
        return {.uv = glm::vec4(1.0f / size, 0.5f, 0.5f),
                .slope_scale = res * 0.5f / size,
                .height_units = params.get<ParamId::wave_height_scale>(),
                .normal_scale = params.get<ParamId::water_normal_strength>()};
    }
    // Capillary: heights in 0.1 mm over texels of wave.size / res metres. The true slope of a difference
    // of 2 texels is (hL - hR) * 0.1 mm / (2 dx); water.normal_strength scales it (1: as the physics has
    // it; the default 2.5 makes shallow rings read from a few metres away).
    const double metres_per_unit = static_cast<double>(params.get<ParamId::puddle_metres_per_unit>());
    const double tile_units = static_cast<double>(params.get<ParamId::wave_size>()) / metres_per_unit;
    const double texel_m = static_cast<double>(params.get<ParamId::wave_size>()) / res_d;
    const float per_unit = static_cast<float>(1.0 / tile_units);
    return {
        .uv = glm::vec4(per_unit, per_unit, 0.5f, 0.5f),
        .slope_scale = glm::vec2(static_cast<float>(0.5 * res_d / tile_units)),
        .height_units = static_cast<float>(capillary_height_unit_m / metres_per_unit),
        .normal_scale = static_cast<float>(static_cast<double>(params.get<ParamId::water_normal_strength>()) *
                                           capillary_height_unit_m / (2.0 * texel_m))};
}

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
    const render::PuddleVariant v = render::choose_puddle_variant(params, env.rgbm, env.cloud_room);
    return renderer.variants.ensure(device, v, [&] { return puddle_desc(v, surface.unorm); });
}

void puddle_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const Clouds& clouds,
                   PuddleRenderer& renderer, const RenderTarget& target, const CameraEnvironment& camera) {
    render_system(device, params, surface, env, ground, clouds, renderer, target, camera.reflection());
}

void render_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const Clouds& clouds,
                   PuddleRenderer& renderer, const RenderTarget& target,
                   const gpu::Texture* environment_override, const render::PuddleVariant* variant) {
    const gpu::FrameTarget& frame = target.target;
    const bool rgbm = env.rgbm && !environment_override;               // the camera cube is sRGB8
    const bool cloud_layer = env.cloud_room && !environment_override;  // the camera's cube has no room
    render::PuddleVariant chosen =
        variant ? *variant : render::choose_puddle_variant(params, rgbm, cloud_layer);
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
        .set_texture(0, surface.texture, surface_sampler(params, surface))
        .set_texture(1, environment_override ? *environment_override : env.cube, env.sampler)
        .set_texture(2, ground.texture, ground.sampler)
        .set_texture(3, clouds.layer, clouds.sampler);
    render::set_param_uniforms(pass, pipeline->params, params);
    pass.set("u_view_window", target.view.uniform())
        .set("u_cam_forward", cam.forward)
        .set("u_cam_right", cam.right)
        .set("u_cam_up", cam.up)
        .set("u_cam_scale", cam.scale)
        .set("u_env_matrix", env_matrix)
        .set("u_env_scale", std::exp2(params.get<ParamId::environment_exposure>()));
    if (chosen.cloud_layer) {
        const auto vec3 = [](const std::array<float, 3>& rgb) { return glm::vec3(rgb[0], rgb[1], rgb[2]); };
        pass.set("u_cloud_offset", clouds.offset)
            .set("u_cloud_scale", 1.0f / assets::cloud_tile_units)
            .set("u_cloud_base", vec3(clouds.light.base))
            .set("u_cloud_top", vec3(clouds.light.top))
            // 25 = 1 / (1 - 0.96): the full halo at the moon (puddle.frag's cos threshold, CloudLight).
            .set("u_cloud_halo", vec3(clouds.light.moon_halo) * 25.0f)
            .set("u_moon_direction", vec3(clouds.light.moon_direction));
    }
    const SurfaceMapping map = surface_mapping(params, surface);
    pass.set("u_surface_map", map.uv)
        .set("u_slope_scale", map.slope_scale)
        .set("u_height_units", map.height_units)
        .set("u_normal_scale", map.normal_scale);
    // The shoreline's ellipse within the puddle's box, placed for the default camera: the far shore and
    // both sides in view, the near water filling the bottom of the frame.
    const glm::vec3 size = params.get<ParamId::puddle_size>();
    pass.set("u_shore", glm::vec4(-0.05f * size.x, 0.08f * size.z, 0.34f * size.x, 0.3f * size.z))
        .set("u_under_filter", 0.7f * (1.0f - 0.5f * params.get<ParamId::water_tint>()))
        .set("u_reflect_gain", 0.5f * params.get<ParamId::water_reflectivity>())
        .set("u_splash_light", 6.0f * params.get<ParamId::look_haze_color>())
        .set("u_tint_glow", 0.15f * params.get<ParamId::water_tint>())
        .set("u_top", 0.5f * size.y)
        .set("u_floor_drop", 0.6f * (0.5f * size.y + params.get<ParamId::puddle_depth>()));
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
