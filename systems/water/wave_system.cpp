#include "systems/water/wave_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "render/shader_hash.hpp"
#include "systems/water/capillary_step.hpp"
#include "systems/water/rain_rate.hpp"

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

bool wave_field_fixed_point(const gpu::Device& device, const params::Params& params) {
    return !(params.get<ParamId::wave_float_field>() && device.caps().float_render_targets);
}

Result<void> build_wave_field(gpu::Device& device, const params::Params& params, WaveField& field) {
    const int n = params.get<ParamId::wave_resolution>();
    const bool fixed_point = wave_field_fixed_point(device, params);
    const gpu::TextureFormat format = fixed_point ? gpu::TextureFormat::RG32I : gpu::TextureFormat::RG32F;
    // A new resolution needs new textures only: compiling the step again on every rebuild grew the process
    // by about 65 KiB each time on llvmpipe (puddle-soak, docs/testing.md), so the pipelines, the sampler and
    // the drop buffer stay with `field`. The textures are replaced only once everything that can fail has
    // worked, so a failed rebuild leaves the field whole.
    WaveField f;
    f.resolution = n;
    f.fixed_point = fixed_point;
    f.capillary = params.get<ParamId::wave_model>() == params::WaveModel::capillary;
    if (auto built = field.step_pipelines.ensure(
            device, f.variant(),
            [&] {
                std::vector<std::string> defines{fmt::format("MAX_DROPS {}", max_drops)};
                if (f.capillary) defines.emplace_back("CAPILLARY");
                if (fixed_point)
                    defines.push_back(fmt::format("FIXED_POINT_SCALE {:.1f}", fixed_point_scale));
                return gpu::PipelineDesc{.label = "wave step",
                                         .fragment = "wave_step.frag",
                                         .defines = defines,
                                         .textures = {"u_field", "u_impact_table"},
                                         .uniform_blocks = {"Drops"}};
            });
        !built)
        return built;
    if (field.drops.id() == 0) {
        // The shader reads texels with texelFetch; a nearest sampler keeps unfilterable formats complete.
        // Repeat: the capillary step reads its periodic neighbours through the wrap (wave_step.frag).
        field.nearest = device.create_sampler({.label = "wave field",
                                               .min = gpu::Filter::Nearest,
                                               .mag = gpu::Filter::Nearest,
                                               .wrap = gpu::Wrap::Repeat});
        auto drops = device.create_buffer({.label = "live drops", .size = sizeof(glm::vec4) * max_drops});
        if (!drops) return drops.error();
        field.drops = std::move(drops).value();
    }
    if (f.capillary && field.rain_cells.id() == 0) {
        if (auto built = field.rain_cells_pipeline.ensure(
                device, {},
                [] { return gpu::PipelineDesc{.label = "rain cells", .fragment = "rain_cells.frag"}; });
            !built)
            return built;
        auto table = device.create_texture({.label = "rain cells",
                                            .format = gpu::TextureFormat::RGBA32I,
                                            .width = 2 * rain_cells_max,
                                            .height = 2 * rain_cells_max,
                                            .render_target = true});
        if (!table) return table.error();
        field.rain_cells = std::move(table).value();
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
    field.capillary = f.capillary;
    return {};
}

namespace {

// A pass of the step shader renders from the newest texture into the other.
gpu::RenderPassDesc step_pass(WaveField& field) {
    const auto next = static_cast<std::size_t>(1 - field.current);
    return {.label = "wave step",
            .target = {&field.textures[next], {field.resolution, field.resolution}},
            .load = gpu::LoadOp::DontCare};
}
void bind_step(gpu::RenderPass& pass, const render::BuiltPipeline& step, const WaveField& field,
               int drop_count) {
    pass.set_pipeline(step.pipeline)
        .set_texture(0, field.newest(), field.nearest)
        .set_uniform_buffer(0, field.drops)
        .set("u_drop_count", drop_count);
}

// The rain cells' table for one pass (rain_cells.frag): 2 cells a side of texels in its corner.
void draw_rain_cells(gpu::Device& device, const WaveField::Rain& rain, glm::vec4 drop_shape,
                     WaveField& field) {
    const render::BuiltPipeline* built = field.rain_cells_pipeline.find({});
    if (!built) return;  // never: build_wave_field builds it with a capillary field
    const int side = 2 * static_cast<int>(rain.rain.x);
    auto pass = device.begin_pass(
        {.label = "rain cells", .target = {&field.rain_cells, {side, side}}, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(built->pipeline)
        .set("u_rain", rain.rain)
        .set("u_slot_keys", rain.slot_keys)
        .set("u_slot_time", rain.slot_time)
        .set("u_drop_shape", drop_shape);
    pass.draw_fullscreen();
}

void capillary_steps(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                     const LiveDrops& drops, const render::BuiltPipeline& step, WaveField& field) {
    const CapillaryStep s = capillary_step(params, clock.step_seconds);
    const double size = static_cast<double>(params.get<ParamId::wave_size>());
    const double cells = std::clamp(std::round(size / rain_cell_m), 1.0, double(rain_cells_max));
    const double cell_m = size / cells;
    const double rate = rain_rate_at(static_cast<double>(params.get<ParamId::rain_rate>()),
                                     static_cast<double>(params.get<ParamId::rain_drift>()), clock.sim_time);
    const double chance =
        std::min(1.0, impacts_per_square_metre_second(rate) * cell_m * cell_m * rain_slot_s);
    // A drop's push in height units per second squared at the peak, per mm^1.5 of drop (wave_step.frag).
    constexpr double drop_accel = 60000.0 / 0.3;
    const auto seed = static_cast<std::int32_t>(params.get<ParamId::rain_seed>());
    const double gain = drop_accel * static_cast<double>(params.get<ParamId::rain_intensity>()) * s.dt * s.dt;
    for (int i = 0; i < s.substeps; ++i) {
        const double back = (s.substeps - 1 - i) * s.dt;  // this pass ends this long before the step
        const double t = clock.sim_time - back;
        const double slot = std::floor(t / rain_slot_s);
        const WaveField::Rain rain{
            .rain = glm::vec4(static_cast<float>(cells), static_cast<float>(field.resolution / cells),
                              static_cast<float>(chance), static_cast<float>(marshall_palmer_slope(rate))),
            .slot_keys = {rain_slot_key(static_cast<std::int64_t>(slot), seed),
                          rain_slot_key(static_cast<std::int64_t>(slot) - 1, seed)},
            .slot_time = static_cast<float>(t - slot * rain_slot_s),
            .texel_mm = static_cast<float>(s.texel_m * 1e3),
            .splash = chance > 0.0 ? std::min(1.0f, params.get<ParamId::rain_intensity>() / 0.3f) : 0.0f};
        field.last_rain = rain;
        const glm::vec4 drop_shape(static_cast<float>(s.texel_m * 1e3), static_cast<float>(gain),
                                   static_cast<float>(-back), 0.0f);
        if (chance > 0.0) draw_rain_cells(device, rain, drop_shape, field);
        auto pass = device.begin_pass(step_pass(field));
        bind_step(pass, step, field, drops.count);
        pass.set("u_step", glm::vec4(s.a, s.b, s.v, s.keep))
            .set("u_level", s.level)
            .set("u_drop_shape", drop_shape)
            .set("u_impacts_on", chance > 0.0 ? 1 : 0)
            .set_texture(1, field.rain_cells, field.nearest)
            .set("u_impact_grid", glm::vec2(rain.rain));
        pass.draw_fullscreen();
        field.current = 1 - field.current;
    }
}

}  // namespace

void wave_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                 const LiveDrops& drops, WaveField& field) {
    const render::BuiltPipeline* step = field.step_pipelines.find(field.variant());
    if (!step) return;  // never: build_wave_field makes a field only with its pipeline built
    if (field.generation != clock.field_generation) {
        field.generation = clock.field_generation;
        for (gpu::Texture& texture : field.textures) clear_texture(device, texture, field.resolution);
    }
    field.drops.write(std::as_bytes(std::span(drops.drops.data(), static_cast<std::size_t>(drops.count))));
    if (field.capillary) {
        capillary_steps(device, params, clock, drops, *step, field);
        return;
    }
    auto pass = device.begin_pass(step_pass(field));
    bind_step(pass, *step, field, drops.count);
    render::set_param_uniforms(pass, step->params, params);
    pass.draw_fullscreen();
    field.current = 1 - field.current;
}

std::int32_t rain_slot_key(std::int64_t slot, std::int32_t seed) {
    constexpr std::uint32_t salt = 0x7261696eu;  // "rain": other hashes of the seed give other patterns
    return static_cast<std::int32_t>(
        render::shader_hash3(static_cast<std::uint32_t>(slot), static_cast<std::uint32_t>(seed), salt));
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
