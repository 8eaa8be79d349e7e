// The passes of a frame at each size: the floor (sample one frame-sized texture, write the frame), the
// wave step, the surface, the puddle render by method, the rain streaks over it, and the whole frame.
#include "bench/pass_benchmarks.hpp"

#include <fmt/format.h>

#include <string>

#include "bench/bench_engine.hpp"
#include "systems/puddle/render_system.hpp"
#include "systems/rain_overlay/rain_overlay_system.hpp"
#include "systems/water/surface_system.hpp"
#include "systems/water/wave_system.hpp"

namespace puddle::bench {

using params::ParamId;
using params::Params;

namespace {

void set_method(Params& params, params::RenderMethod method) {
    // CommandLine is the highest source, so this always takes.
    params.set<ParamId::render_method>(method, params::ParamSource::CommandLine);
}

void bench_floor(benchmark::State& state, glm::ivec2 size) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    gpu::Device& device = b->engine->device();
    const gpu::FrameTarget target = b->engine->display().frame_target();
    measure(state, device, [&] {
        auto pass = device.begin_pass({.label = "floor", .target = target, .load = gpu::LoadOp::DontCare});
        pass.set_pipeline(b->floor).set_texture(0, b->source, b->sampler);
        pass.draw_fullscreen();
    });
}

// The simulate stage (begin step, drops, wave), once. The field has its own resolution, so the display
// size does not matter here.
void bench_wave_step(benchmark::State& state, glm::ivec2 size) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    app::Engine& engine = *b->engine;
    measure(state, engine.device(), [&] { engine.run_stage(ecs::Stage::Simulate); });
}

void bench_surface(benchmark::State& state, glm::ivec2 size) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    ecs::World& w = b->engine->world();
    gpu::Device& device = b->engine->device();
    measure(state, device, [&] {
        systems::surface_system(device, w.resource<systems::WaveField>(), w.resource<systems::Surface>());
    });
}

void bench_render(benchmark::State& state, glm::ivec2 size, params::RenderMethod method) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    ecs::World& w = b->engine->world();
    gpu::Device& device = b->engine->device();
    set_method(w.resource<Params>(), method);
    measure(state, device, [&] {
        systems::render_system(device, w.resource<Params>(), w.resource<systems::Surface>(),
                               w.resource<systems::Environment>(), w.resource<systems::Ground>(),
                               w.resource<systems::Clouds>(), w.resource<systems::PuddleRenderer>(),
                               w.resource<systems::RenderTarget>());
    });
}

// The rain streaks (overlay.rain, on in the default look) blended over the frame's scene.
void bench_rain_overlay(benchmark::State& state, glm::ivec2 size) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    ecs::World& w = b->engine->world();
    gpu::Device& device = b->engine->device();
    measure(state, device, [&] {
        systems::rain_overlay_system(device, w.resource<Params>(), w.resource<systems::FrameClock>(),
                                     w.resource<systems::RainOverlay>(), w.resource<systems::RenderTarget>());
    });
}

// A whole frame at 60 Hz: exactly one wave step (at the default 60 steps/s), surface, render, present.
void bench_frame(benchmark::State& state, glm::ivec2 size, params::RenderMethod method,
                 Start start = Start::steady) {
    Bench* b = bench_for(size, state, start);
    if (!b) return;
    set_method(b->engine->params(), method);
    std::string error;
    measure(state, b->engine->device(), [&] {
        if (auto r = b->engine->frame(1.0 / 60.0); !r) error = r.error().message;
    });
    if (!error.empty()) state.SkipWithError(error.c_str());
}

}  // namespace

void register_pass_benchmarks() {
    for (glm::ivec2 s : sizes) {
        const std::string n = size_name(s);
        add_benchmark("floor/" + n, [s](benchmark::State& st) { bench_floor(st, s); });
        if (s == sizes[0])
            add_benchmark(fmt::format("wave_step/{}", Params{}.get<ParamId::wave_resolution>()),
                          [s](benchmark::State& st) { bench_wave_step(st, s); });
        add_benchmark("surface/" + n, [s](benchmark::State& st) { bench_surface(st, s); });
        for (params::RenderMethod m : methods)
            add_benchmark(fmt::format("render/{}/{}", params::choice_name(m), n),
                          [s, m](benchmark::State& st) { bench_render(st, s, m); });
        add_benchmark("rain_overlay/" + n, [s](benchmark::State& st) { bench_rain_overlay(st, s); });
        for (params::RenderMethod m : methods)
            add_benchmark(fmt::format("frame/{}/{}", params::choice_name(m), n),
                          [s, m](benchmark::State& st) { bench_frame(st, s, m); });
    }
}

void register_calm_start_benchmarks() {
    for (glm::ivec2 s : sizes)
        add_benchmark(fmt::format("frame_calm_start/{}/{}", params::choice_name(methods[0]), size_name(s)),
                      [s](benchmark::State& st) { bench_frame(st, s, methods[0], Start::calm); });
}

}  // namespace puddle::bench
