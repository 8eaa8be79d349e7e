#include "bench/bench_engine.hpp"

#include <fmt/format.h>

#include <vector>

#include "bench/camera_benchmarks.hpp"
#include "systems/puddle/puddle_plugin.hpp"

namespace puddle::bench {

namespace {

std::unique_ptr<Bench> current;  // one at a time: each engine owns an EGL context that it makes current
std::string renderer_text = "(no engine was made)";
std::vector<std::pair<glm::ivec2, Warmup>> warmups_done;

}  // namespace

std::string size_name(glm::ivec2 s) {
    return fmt::format("{}x{}", s.x, s.y);
}

const std::string& renderer() {
    return renderer_text;
}

namespace {

Result<std::unique_ptr<Bench>> make_bench(glm::ivec2 size, Start start) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = size;
    auto engine = app::Engine::create(params::Params{}, display, {}, {systems::add_puddle_plugin});
    if (!engine) return engine.error();
    auto b = std::make_unique<Bench>();
    b->size = size;
    b->start = start;
    b->engine = std::move(engine).value();
    gpu::Device& device = b->engine->device();
    renderer_text = fmt::format("{} ({})", device.caps().renderer, device.caps().version);

    auto floor = device.create_pipeline({.label = "bench floor",
                                         .vertex = "fullscreen.vert",
                                         .fragment = "floor.frag",
                                         .textures = {"u_source"}});
    if (!floor) return floor.error();
    b->floor = std::move(floor).value();
    auto source = device.create_texture({.label = "bench source", .width = size.x, .height = size.y});
    if (!source) return source.error();
    b->source = std::move(source).value();
    b->source.upload(std::vector<std::byte>(static_cast<std::size_t>(size.x) * size.y * 4, std::byte{128}));
    // Linear, as a pass reading a video frame or an image would sample it.
    b->sampler = device.create_sampler({.label = "bench source"});

    // One frame of a whole second (16 steps, the per-frame cap) so the surface has ripples on it and the
    // render target resource is set; then the rain runs until the water is as rough as it gets, and one
    // more frame renders that surface.
    if (auto r = b->engine->frame(1.0); !r) return r.error();
    if (start == Start::steady) {
        b->warmup = warm_to_steady_state(*b->engine);
        warmups_done.emplace_back(size, b->warmup);
        if (auto r = b->engine->frame(1.0 / 60.0); !r) return r.error();
    }
    return b;
}

}  // namespace

Bench* bench_for(glm::ivec2 size, benchmark::State& state, Start start) {
    if (current && current->size == size && current->start == start) return current.get();
    release_camera_bench();
    current.reset();
    auto b = make_bench(size, start);
    if (!b) {
        state.SkipWithError(b.error().message.c_str());
        return nullptr;
    }
    current = std::move(b).value();
    return current.get();
}

const std::vector<std::pair<glm::ivec2, Warmup>>& warmups() {
    return warmups_done;
}

Bench* current_bench() {
    return current.get();
}

void release_benches() {
    release_camera_bench();
    current.reset();
}

void add_benchmark(const std::string& name, std::function<void(benchmark::State&)> fn) {
    benchmark::RegisterBenchmark(name.c_str(), std::move(fn))->UseRealTime()->Unit(benchmark::kMillisecond);
}

}  // namespace puddle::bench
