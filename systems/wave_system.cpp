#include "systems/wave_system.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <span>

namespace puddle::systems {

using params::ParamId;

namespace {

// A flat, still surface: both steps zero.
void clear_texture(gpu::Device& device, gpu::Texture& texture, int n) {
    device.begin_pass({.label = "wave clear",
                       .target = {&texture, {n, n}},
                       .load = gpu::LoadOp::Clear,
                       .clear = {0, 0, 0, 0}});
}

}  // namespace

Result<void> build_wave_field(gpu::Device& device, const params::Params& params, WaveField& field) {
    const int n = params.get<ParamId::wave_resolution>();
    const bool fixed_point = !(params.get<ParamId::wave_float_field>() && device.caps().float_render_targets);
    const gpu::TextureFormat format = fixed_point ? gpu::TextureFormat::RG32I : gpu::TextureFormat::RG32F;
    // A new resolution needs new textures only: compiling the step again on every rebuild grew the process
    // by about 65 KiB each time on llvmpipe (puddle-soak, docs/testing.md), so the pipelines, the sampler and
    // the drop buffer stay with `field`. The textures are replaced only once everything that can fail has
    // worked, so a failed rebuild leaves the field whole.
    WaveField f;
    f.resolution = n;
    f.fixed_point = fixed_point;
    if (auto built = field.step_pipelines.ensure(
            device, f.encoding(),
            [&] {
                std::vector<std::string> defines{fmt::format("MAX_DROPS {}", max_drops)};
                if (fixed_point)
                    defines.push_back(fmt::format("FIXED_POINT_SCALE {:.1f}", fixed_point_scale));
                return gpu::PipelineDesc{.label = "wave step",
                                         .fragment = "wave_step.frag",
                                         .defines = defines,
                                         .textures = {"u_field"},
                                         .uniform_blocks = {"Drops"}};
            });
        !built)
        return built;
    if (field.drops.id() == 0) {
        // The shader reads texels with texelFetch; a nearest sampler keeps unfilterable formats complete.
        field.nearest = device.create_sampler(
            {.label = "wave field", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
        auto drops = device.create_buffer({.label = "live drops", .size = sizeof(glm::vec4) * max_drops});
        if (!drops) return drops.error();
        field.drops = std::move(drops).value();
    }
    for (int i = 0; i < 2; ++i) {
        auto texture = device.create_texture({.label = fmt::format("wave field {}", i),
                                              .format = format,
                                              .width = n,
                                              .height = n,
                                              .render_target = true});
        if (!texture) return texture.error();
        f.textures[static_cast<std::size_t>(i)] = std::move(texture).value();
        clear_texture(device, f.textures[static_cast<std::size_t>(i)], n);
    }
    field.textures = std::move(f.textures);
    field.current = 0;
    field.resolution = n;
    field.fixed_point = fixed_point;
    return {};
}

void wave_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                 const LiveDrops& drops, WaveField& field) {
    const render::BuiltPipeline* step = field.step_pipelines.find(field.encoding());
    if (!step) return;  // never: build_wave_field makes a field only with its pipeline built
    if (field.generation != clock.field_generation) {
        field.generation = clock.field_generation;
        for (gpu::Texture& texture : field.textures) clear_texture(device, texture, field.resolution);
    }
    const auto next = static_cast<std::size_t>(1 - field.current);
    field.drops.write(std::as_bytes(std::span(drops.drops.data(), static_cast<std::size_t>(drops.count))));
    auto pass = device.begin_pass({.label = "wave step",
                                   .target = {&field.textures[next], {field.resolution, field.resolution}},
                                   .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(step->pipeline)
        .set_texture(0, field.newest(), field.nearest)
        .set_uniform_buffer(0, field.drops)
        .set("u_drop_count", drops.count);
    render::set_param_uniforms(pass, step->params, params);
    pass.draw_fullscreen();
    field.current = static_cast<int>(next);
}

std::vector<float> WaveField::read_heights(gpu::Device& device) const {
    std::vector<float> texels = device.read_texture(newest());
    std::vector<float> out(static_cast<std::size_t>(resolution) * resolution * 2);
    const float scale = fixed_point ? 1.0f / fixed_point_scale : 1.0f;
    for (std::size_t i = 0; i < out.size() / 2; ++i) {
        out[2 * i] = texels[4 * i] * scale;
        out[2 * i + 1] = texels[4 * i + 1] * scale;
    }
    return out;
}

}  // namespace puddle::systems
