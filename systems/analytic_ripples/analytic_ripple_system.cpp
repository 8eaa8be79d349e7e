#include "systems/analytic_ripples/analytic_ripple_system.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include "systems/water/drop_system.hpp"

namespace puddle::systems {

using params::ParamId;

AnalyticSource sample_analytic_source(const params::Params& params, int slot, int slots, double now,
                                      int field_resolution) {
    const double lifetime = params.get<ParamId::analytic_lifetime>();
    const double offset = static_cast<double>(slot) / static_cast<double>(std::max(slots, 1));
    const double life = std::floor(now / lifetime - offset);
    const double birth = (life + offset) * lifetime;
    const DropSample drop =
        sample_drop(static_cast<std::uint32_t>(params.get<ParamId::rain_seed>()), slot,
                    static_cast<std::int64_t>(life), params.get<ParamId::analytic_amplitude>());
    return {.position = drop.position * static_cast<float>(field_resolution),
            .age = static_cast<float>(now - birth),
            .amplitude = drop.strength,
            .spatial_decay = params.get<ParamId::analytic_spatial_decay>(),
            .temporal_decay = params.get<ParamId::analytic_temporal_decay>(),
            .frequency_decay = params.get<ParamId::analytic_frequency_decay>(),
            .angular_frequency = params.get<ParamId::analytic_angular_frequency>(),
            .speed = params.get<ParamId::analytic_speed>(),
            .max_phase = static_cast<float>(2.0 * std::numbers::pi * params.get<ParamId::analytic_rings>())};
}

double analytic_height(const AnalyticSource& s, double d) {
    const double tau = s.age, speed = s.speed, omega = s.angular_frequency;
    const double l1 = s.spatial_decay, l2 = s.temporal_decay, l3 = s.frequency_decay;
    const double x = tau - d / speed;
    if (x <= 0) return 0;
    const double phase = omega / (1.0 + l3 * tau) * x;
    if (phase >= static_cast<double>(s.max_phase)) return 0;
    return static_cast<double>(s.amplitude) / (1.0 + l1 * d * d + l2 * tau * tau) *
           std::cos(phase - std::numbers::pi / 2);
}

void set_analytic_source(AnalyticRipples& ripples, int index, const AnalyticSource& s) {
    glm::vec4* row = &ripples.texels[static_cast<std::size_t>(index) * texels_per_source];
    // The first texel is all the shader needs to skip a source whose front has not arrived.
    row[0] = {s.position, s.age, s.speed};
    row[1] = {s.spatial_decay, s.temporal_decay, s.frequency_decay, s.angular_frequency};
    row[2] = {s.amplitude, s.max_phase, 0, 0};
}

namespace {
gpu::PipelineDesc analytic_ripples_desc(const Surface& surface) {
    std::vector<std::string> defines;
    if (surface.unorm) defines.emplace_back("SURFACE_UNORM");
    return {.label = "analytic ripples",
            .fragment = "analytic_ripples.frag",
            .defines = defines,
            .textures = {"u_sources"}};
}

// The data texture, made once.
Result<void> make_sources(gpu::Device& device, AnalyticRipples& ripples) {
    if (ripples.sources) return {};
    auto sources = device.create_texture({.label = "analytic sources",
                                          .format = gpu::TextureFormat::RGBA32F,
                                          .width = texels_per_source,
                                          .height = max_analytic_sources});
    if (!sources) return sources.error();
    ripples.sources = std::move(sources).value();
    ripples.nearest = device.create_sampler(
        {.label = "analytic sources", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
    return {};
}
}  // namespace

bool request_analytic_ripples(gpu::Device& device, const Surface& surface, AnalyticRipples& ripples) {
    if (!ripples.pass.request(device, {}, [&] { return analytic_ripples_desc(surface); })) return false;
    if (auto made = make_sources(device, ripples); !made) {
        ripples.pass.fail({},
                          made.error());  // like a shader that did not build: one line, then nothing drawn
        return false;
    }
    return true;
}

Result<void> prepare_analytic_ripples(gpu::Device& device, const Surface& surface, AnalyticRipples& ripples) {
    if (auto r = ripples.pass.ensure(device, {}, [&] { return analytic_ripples_desc(surface); }); !r)
        return r;
    return make_sources(device, ripples);
}

void analytic_ripple_pass(gpu::Device& device, AnalyticRipples& ripples, Surface& surface) {
    const render::BuiltPipeline* built = ripples.pass.find({});
    if (!built) return;
    ripples.sources.upload(std::as_bytes(std::span(ripples.texels)));
    auto pass = device.begin_pass({.label = "analytic ripples",
                                   .target = {&surface.texture, {surface.resolution, surface.resolution}},
                                   .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(built->pipeline)
        .set_texture(0, ripples.sources, ripples.nearest)
        .set("u_source_count", ripples.count);
    pass.draw_fullscreen();
}

void analytic_ripple_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                            AnalyticRipples& ripples, Surface& surface) {
    if (!request_analytic_ripples(device, surface, ripples)) return;  // a failure is logged once
    ripples.count = std::min(params.get<ParamId::analytic_sources>(), max_analytic_sources);
    for (int i = 0; i < ripples.count; ++i)
        set_analytic_source(
            ripples, i, sample_analytic_source(params, i, ripples.count, clock.sim_time, surface.resolution));
    analytic_ripple_pass(device, ripples, surface);
}

void add_analytic_ripples_plugin(ecs::World& world, ecs::Schedule& schedule) {
    auto& ripples = world.insert_resource<AnalyticRipples>();
    const Surface& surface = world.resource<Surface>();
    world.resource<Looks>().entries.push_back(
        {.scene = Scene::puddle,
         .drops = DropModel::analytic,
         .prepare = [&surface,
                     &ripples](gpu::Device& d) { return prepare_analytic_ripples(d, surface, ripples); },
         .request = [&surface,
                     &ripples](gpu::Device& d) { return request_analytic_ripples(d, surface, ripples); }});
    schedule.add(ecs::Stage::Render, "analytic ripples", analytic_ripple_system)
        .run_if(drops_are(DropModel::analytic))
        .run_if(output_on());
}

}  // namespace puddle::systems
