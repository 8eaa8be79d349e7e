#include "systems/surface_system.hpp"

#include <fmt/format.h>

namespace puddle::systems {

Result<void> build_surface(gpu::Device& device, const WaveField& field, Surface& surface) {
    Surface s;
    s.resolution = field.resolution;
    s.unorm = !device.caps().half_float_render_targets;
    s.field_fixed_point = field.fixed_point;
    // A new resolution: the same shader, a new texture (see build_wave_field); the old surface keeps its
    // pipeline until the new texture exists.
    const bool reuse = surface.pipeline.id() != 0 && surface.unorm == s.unorm &&
                       surface.field_fixed_point == s.field_fixed_point;
    if (!reuse) {
        std::vector<std::string> defines;
        if (s.unorm) defines.emplace_back("SURFACE_UNORM");
        if (field.fixed_point) defines.push_back(fmt::format("FIXED_POINT_SCALE {:.1f}", fixed_point_scale));
        auto pipeline = device.create_pipeline(
            {.label = "surface", .fragment = "surface.frag", .defines = defines, .textures = {"u_field"}});
        if (!pipeline) return pipeline.error();
        s.pipeline = std::move(pipeline).value();
    }
    auto texture =
        device.create_texture({.label = "surface",
                               .format = s.unorm ? gpu::TextureFormat::RGBA8 : gpu::TextureFormat::RGBA16F,
                               .width = field.resolution,
                               .height = field.resolution,
                               .render_target = true});
    if (!texture) return texture.error();
    s.texture = std::move(texture).value();
    if (reuse) s.pipeline = std::move(surface.pipeline);
    s.field_sampler =
        device.create_sampler({.label = "field", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
    s.sampler =
        device.create_sampler({.label = "surface", .min = gpu::Filter::Linear, .mag = gpu::Filter::Linear});
    surface = std::move(s);
    return {};
}

void surface_system(gpu::Device& device, const WaveField& field, Surface& surface) {
    auto pass = device.begin_pass({.label = "surface",
                                   .target = {&surface.texture, {surface.resolution, surface.resolution}},
                                   .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(surface.pipeline).set_texture(0, field.newest(), surface.field_sampler);
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
