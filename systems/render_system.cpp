#include "systems/render_system.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "systems/param_uniforms.hpp"

namespace puddle::systems {

using params::ParamId;

Result<void> build_puddle_renderer(gpu::Device& device, const Surface& surface, PuddleRenderer& renderer) {
    std::vector<std::string> defines;
    if (surface.unorm) defines.emplace_back("SURFACE_UNORM");
    auto intersect = device.create_pipeline({.label = "puddle (intersect)",
                                             .fragment = "puddle.frag",
                                             .defines = defines,
                                             .textures = {"u_surface", "u_env", "u_ground"}});
    if (!intersect) return intersect.error();
    defines.emplace_back("METHOD_RAYMARCH");
    auto raymarch = device.create_pipeline({.label = "puddle (raymarch)",
                                            .fragment = "puddle.frag",
                                            .defines = defines,
                                            .textures = {"u_surface", "u_env", "u_ground"}});
    if (!raymarch) return raymarch.error();
    renderer.intersect = std::move(intersect).value();
    renderer.raymarch = std::move(raymarch).value();
    return {};
}

void render_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const PuddleRenderer& renderer,
                   const RenderTarget& target, const gpu::Texture* environment_override) {
    const gpu::FrameTarget& frame = target.target;
    const bool raymarch = params.s(ParamId::render_method) == "raymarch";

    // Everything uniform across the screen is worked out here once, not per pixel.
    const glm::vec3 eye = params.v3(ParamId::camera_position);
    glm::vec3 forward = params.v3(ParamId::camera_target) - eye;
    forward = glm::length(forward) > 1e-6f ? glm::normalize(forward) : glm::vec3(0, 0, -1);
    glm::vec3 right = glm::cross(forward, glm::vec3(0, 1, 0));
    right = glm::length(right) > 1e-6f ? glm::normalize(right) : glm::vec3(1, 0, 0);  // looking straight down
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(glm::radians(params.f(ParamId::camera_fov)) * 0.5f);
    const float aspect = static_cast<float>(frame.size.x) / static_cast<float>(std::max(frame.size.y, 1));
    const float a = params.f(ParamId::environment_rotation);
    // Column-major rotation about +Y.
    const glm::mat3 env_matrix(std::cos(a), 0, -std::sin(a), 0, 1, 0, std::sin(a), 0, std::cos(a));

    auto pass = device.begin_pass({.label = "puddle", .target = frame, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(raymarch ? renderer.raymarch : renderer.intersect)
        .set_texture(0, surface.texture, surface.sampler)
        .set_texture(1, environment_override ? *environment_override : env.cube, env.sampler)
        .set_texture(2, ground.texture, ground.sampler);
    set_param_uniforms(pass, params);
    pass.set("u_cam_forward", forward)
        .set("u_cam_right", right)
        .set("u_cam_up", up)
        .set("u_cam_scale", glm::vec2(tan_half * aspect, tan_half))
        .set("u_env_matrix", env_matrix)
        .set("u_env_rgbm", env.rgbm && !environment_override ? 1 : 0)  // the camera cube is sRGB8
        .set("u_env_scale", std::exp2(params.f(ParamId::environment_exposure)));
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
