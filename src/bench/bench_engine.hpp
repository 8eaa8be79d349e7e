#pragma once
// The engines puddle-bench measures: one headless engine per frame size (one at a time: each owns an EGL
// context it makes current), the floor pass's objects beside it, and the timing loop every benchmark
// shares. Every measurement ends with Device::finish() inside the timed region: GL calls only queue work,
// so without it a pass would look as cheap as its API calls.

#include <benchmark/benchmark.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/engine.hpp"
#include "bench/steady_state.hpp"

namespace puddle::bench {

inline constexpr std::array<glm::ivec2, 2> sizes{glm::ivec2{1280, 720}, glm::ivec2{1920, 1080}};
inline constexpr std::array<params::RenderMethod, 2> methods{params::RenderMethod::intersect,
                                                             params::RenderMethod::raymarch};

// Where the water is when timing starts: the steady state a wall shows all day (bench/steady_state.hpp),
// or a calm start (one second of rain), the figure kept as a labelled extra.
enum class Start { steady, calm };

// The engine for one frame size plus the floor pass's own objects.
struct Bench {
    glm::ivec2 size{};
    Start start = Start::steady;
    Warmup warmup;  // the steps that warmed it (none for a calm start)
    std::unique_ptr<app::Engine> engine;
    gpu::Pipeline floor;
    gpu::Texture source;
    gpu::Sampler sampler;
};

std::string size_name(glm::ivec2 s);
// "llvmpipe (LLVM 15.0.6, 256 bits) (OpenGL ES 3.2 Mesa 22.3.6)", once an engine was made.
const std::string& renderer();

// The engine of `size`, made on first use: a rainy second already run, then (Start::steady) warmed to the
// steady state. Benchmarks are registered size by size, so each size is built once; the old engine goes
// first. Null, with the benchmark skipped and the reason given, when it cannot be made.
Bench* bench_for(glm::ivec2 size, benchmark::State& state, Start start = Start::steady);
// The warm-ups done so far, by size, for the summary.
const std::vector<std::pair<glm::ivec2, Warmup>>& warmups();
// The engine made last, or null.
Bench* current_bench();
// Releases the engine and everything made in its context (call before exit, ahead of driver teardown).
void release_benches();

// One untimed run first (llvmpipe compiles shader variants on first draw), then the timed loop.
template <class Work>
void measure(benchmark::State& state, gpu::Device& device, Work&& work) {
    work();
    device.finish();
    for (auto _ : state) {
        work();
        device.finish();
    }
}

// Registers a benchmark timed in real milliseconds.
void add_benchmark(const std::string& name, std::function<void(benchmark::State&)> fn);

}  // namespace puddle::bench
