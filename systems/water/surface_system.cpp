#include "systems/water/surface_system.hpp"

#include <fmt/format.h>

namespace puddle::systems {

Result<void> build_surface(gpu::Device& device, const WaveField& field, Surface& surface) {
    const SurfaceVariant variant{!device.caps().half_float_render_targets, field.fixed_point,
                                 field.capillary};
    // A new resolution: the same shader, a new texture (see build_wave_field).
    if (auto built = surface.pipelines.ensure(
            device, variant,
            [&] {
                std::vector<std::string> defines;
                if (variant.unorm) defines.emplace_back("SURFACE_UNORM");
                if (variant.periodic) defines.emplace_back("PERIODIC");
                if (variant.field_fixed_point)
                    defines.push_back(fmt::format("FIXED_POINT_SCALE {:.1f}", fixed_point_scale));
                return gpu::PipelineDesc{.label = "surface",
                                         .fragment = "surface.frag",
                                         .defines = defines,
                                         .textures = {"u_field", "u_impact_table"}};
            });
        !built)
        return built;
    auto texture = device.create_texture(
        {.label = "surface",
         .format = variant.unorm ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::RGBA16F,
         .width = field.resolution,
         .height = field.resolution,
         .mip_levels = gpu::full_mip_count(field.resolution),
         .render_target = true});
    if (!texture) return texture.error();
    surface.texture = std::move(texture).value();
    surface.resolution = field.resolution;
    surface.unorm = variant.unorm;
    surface.field_fixed_point = variant.field_fixed_point;
    surface.periodic = variant.periodic;
    if (surface.sampler.id() == 0) {
        surface.field_sampler = device.create_sampler(
            {.label = "field", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
        surface.sampler = device.create_sampler(
            {.label = "surface", .min = gpu::Filter::Linear, .mag = gpu::Filter::Linear});
        // Trilinear, not anisotropic: toward the horizon the repeated field's footprint spans many tiles,
        // and llvmpipe's anisotropic filter (Mesa 22.3) then takes minutes a frame; the mip chain alone
        // keeps distant rings from sparkling.
        surface.tiled_sampler = device.create_sampler({.label = "tiled surface",
                                                       .min = gpu::Filter::Linear,
                                                       .mag = gpu::Filter::Linear,
                                                       .mipmaps = true,
                                                       .wrap = gpu::Wrap::Repeat});
        surface.marched_sampler = device.create_sampler({.label = "marched surface",
                                                         .min = gpu::Filter::Linear,
                                                         .mag = gpu::Filter::Linear,
                                                         .wrap = gpu::Wrap::Repeat});
    }
    return {};
}

void surface_system(gpu::Device& device, const WaveField& field, Surface& surface) {
    const render::BuiltPipeline* built = surface.pipelines.find(surface.variant());
    if (!built) return;  // never: build_surface makes a surface only with its pipeline built
    auto pass = device.begin_pass({.label = "surface",
                                   .target = {&surface.texture, {surface.resolution, surface.resolution}},
                                   .load = gpu::LoadOp::DontCare});
    // The periodic field's neighbours wrap through its repeating sampler; the reference's clamp.
    pass.set_pipeline(built->pipeline)
        .set_texture(0, field.newest(), surface.periodic ? field.nearest : surface.field_sampler);
    if (surface.periodic)
        pass.set_texture(1, field.rain_cells, surface.field_sampler)
            .set("u_impact_grid", glm::vec2(field.last_rain.rain))
            .set("u_texel_mm", field.last_rain.texel_mm)
            .set("u_splash_gain", field.last_rain.splash);
    pass.draw_fullscreen();
    if (surface.periodic) surface.texture.generate_mipmaps();
}

bool surface_tiled(const params::Params& params) {
    return params.get<params::ParamId::wave_model>() == params::WaveModel::capillary &&
           params.get<params::ParamId::drops_model>() == params::DropsModel::pulse;
}

const gpu::Sampler& surface_sampler(const params::Params& params, const Surface& surface) {
    if (!surface_tiled(params)) return surface.sampler;
    const bool marched = params.get<params::ParamId::render_method>() == params::RenderMethod::raymarch;
    return marched ? surface.marched_sampler : surface.tiled_sampler;
}

}  // namespace puddle::systems
