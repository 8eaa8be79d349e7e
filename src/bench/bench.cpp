// puddle-bench: what each pass of a frame costs, headless, next to a floor (the cheapest useful
// fullscreen pass: sample one frame-sized RGBA8 texture, write the frame). Ratios to the floor travel
// between machines better than milliseconds do, and raymarch/intersect is the figure DESIGN.md
// ("Fidelity and speed") asks for.
//
// Run:   build/puddle-bench                                    (a few minutes on llvmpipe)
//        build/puddle-bench --benchmark_filter='look|drop_pass'  (scenes and drop models only)
//        build/puddle-bench --benchmark_filter='render|floor'  (any Google Benchmark flag works)
//        build/puddle-bench --benchmark_min_time=0.5           (quicker; the default here is 2 s)
//        build/puddle-bench --update-baseline                  (store this run's ratios as the baseline)
//        build/puddle-bench --baseline=FILE                    (compare with another baseline file)
// The summary table goes to stdout after the runs; with --benchmark_format=json prefer
// --benchmark_out=FILE so the table does not mix with the JSON.
//
// After the table: the render shader's estimated per-pixel cost (texture fetches and ALU operations,
// bench/shader_cost.hpp) for both methods, then a check against the stored baseline
// (src/bench/bench_baseline.json): ratios to the floor and the shader cost, never milliseconds. A figure
// over its baseline by more than the tolerance is flagged REGRESSION; the exit status is 1 when the
// shader cost (exact, so a real change) regressed. A ratio only warns: on a shared machine one run's
// ratio can be off by half; repeat the run before believing it.
//
// Every measurement ends with Device::finish() inside the timed region: GL calls only queue work, so
// without it a pass would look as cheap as its API calls.

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/engine.hpp"
#include "assets/procedural.hpp"
#include "bench/bench_baseline.hpp"
#include "bench/shader_cost.hpp"
#include "camera/mjpeg_decoder.hpp"
#include "camera/mjpeg_encoder.hpp"
#include "gpu/shader_source.hpp"
#include "params/config_loader.hpp"
#include "systems/analytic_ripple_system.hpp"
#include "systems/camera_environment.hpp"
#include "systems/drop_system.hpp"
#include "systems/frame_clock.hpp"
#include "systems/grid_drop_system.hpp"
#include "systems/puddle_plugin.hpp"
#include "systems/render_system.hpp"
#include "systems/scene_select.hpp"
#include "systems/surface_system.hpp"
#include "systems/wave_system.hpp"

namespace puddle::bench {

using params::ParamId;
using params::Params;

constexpr std::array<glm::ivec2, 2> sizes{glm::ivec2{1280, 720}, glm::ivec2{1920, 1080}};
constexpr std::array<const char*, 2> methods{"intersect", "raymarch"};

// The engine for one frame size plus the floor pass's own objects.
struct Bench {
    glm::ivec2 size{};
    std::unique_ptr<app::Engine> engine;
    gpu::Pipeline floor;
    gpu::Texture source;
    gpu::Sampler sampler;
};

std::unique_ptr<Bench> current;  // one at a time: each engine owns an EGL context that it makes current
std::string renderer = "(no engine was made)";

std::string size_name(glm::ivec2 s) {
    return fmt::format("{}x{}", s.x, s.y);
}

Result<std::unique_ptr<Bench>> make_bench(glm::ivec2 size) {
    platform::DisplayOptions display;
    display.backend = platform::BackendKind::Headless;
    display.size = size;
    auto engine = app::Engine::create(Params{}, display, {}, {systems::add_puddle_plugin});
    if (!engine) return engine.error();
    auto b = std::make_unique<Bench>();
    b->size = size;
    b->engine = std::move(engine).value();
    gpu::Device& device = b->engine->device();
    renderer = fmt::format("{} ({})", device.caps().renderer, device.caps().version);

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
    // render target resource is set; the passes below then measure a settled, rainy puddle.
    if (auto r = b->engine->frame(1.0); !r) return r.error();
    return b;
}

// The engine of `size`, made on first use. Benchmarks are registered size by size, so each size is
// built once; the old engine goes first so only one EGL context exists at a time.
void release_camera_bench();  // its GPU objects belong to the current engine's context

Bench* bench_for(glm::ivec2 size, benchmark::State& state) {
    if (current && current->size == size) return current.get();
    release_camera_bench();
    current.reset();
    auto b = make_bench(size);
    if (!b) {
        state.SkipWithError(b.error().message.c_str());
        return nullptr;
    }
    current = std::move(b).value();
    return current.get();
}

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

void set_method(Params& params, const char* method) {
    // CommandLine is the highest source, so this always takes.
    params.set(ParamId::render_method, std::string(method), params::ParamSource::CommandLine);
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

void bench_render(benchmark::State& state, glm::ivec2 size, const char* method) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    ecs::World& w = b->engine->world();
    gpu::Device& device = b->engine->device();
    set_method(w.resource<Params>(), method);
    measure(state, device, [&] {
        systems::render_system(device, w.resource<Params>(), w.resource<systems::Surface>(),
                               w.resource<systems::Environment>(), w.resource<systems::Ground>(),
                               w.resource<systems::PuddleRenderer>(), w.resource<systems::RenderTarget>());
    });
}

// A whole frame at 60 Hz: exactly one wave step (at the default 60 steps/s), surface, render, present.
void bench_frame(benchmark::State& state, glm::ivec2 size, const char* method) {
    Bench* b = bench_for(size, state);
    if (!b) return;
    set_method(b->engine->params(), method);
    std::string error;
    measure(state, b->engine->device(), [&] {
        if (auto r = b->engine->frame(1.0 / 60.0); !r) error = r.error().message;
    });
    if (!error.empty()) state.SkipWithError(error.c_str());
}

// --- camera frames (issue 4): what one 1280x720 camera frame costs -------------------------------------
// cpu: the copy (glTexSubImage2D of a YUYV frame, padded rows as drivers give them) or the MJPEG decode;
// gpu: the YUV conversion pass plus the six small environment cube faces and their mipmaps. The
// zero-copy path needs a dmabuf exporter; where EGL has no dmabuf import (llvmpipe), the external
// sampler is measured over an EGLImage of a GL texture, which is its sampling cost without the import.
constexpr glm::ivec2 camera_size{1280, 720};

struct CameraBench {
    systems::CameraEnvironment env;
    std::vector<std::byte> yuyv;
    camera::CameraImage image;
};

std::unique_ptr<CameraBench> camera_current;  // lives with `current`, released before it

void release_camera_bench() {
    camera_current.reset();
}

CameraBench* camera_bench(benchmark::State& state) {
    Bench* b = bench_for(sizes[0], state);
    if (!b) return nullptr;
    if (camera_current) return camera_current.get();
    camera_current = std::make_unique<CameraBench>();
    CameraBench* cb = camera_current.get();
    if (auto r = systems::build_camera_pipelines(b->engine->device(), cb->env); !r) {
        state.SkipWithError(r.error().message.c_str());
        return nullptr;
    }
    const int stride = camera_size.x * 2 + 64;
    cb->yuyv.assign(static_cast<std::size_t>(stride) * camera_size.y, std::byte{128});
    for (std::size_t i = 0; i < cb->yuyv.size(); i += 7) cb->yuyv[i] = std::byte(i & 0xff);
    cb->image = {.layout = camera::PixelLayout::Yuyv,
                 .width = camera_size.x,
                 .height = camera_size.y,
                 .stride = stride,
                 .data = cb->yuyv,
                 .matrix = camera::YuvMatrix::Bt709};
    return cb;
}

void bench_camera_copy(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    gpu::Device& device = current->engine->device();
    measure(state, device, [&] { (void)systems::upload_camera_frame(device, cb->image, cb->env); });
}

void bench_camera_gpu(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    ecs::World& w = current->engine->world();
    gpu::Device& device = current->engine->device();
    (void)systems::upload_camera_frame(device, cb->image, cb->env);
    measure(state, device, [&] {
        cb->env.convert_due = true;  // as after each new frame
        systems::camera_environment_system(device, w.resource<Params>(), w.resource<systems::Environment>(),
                                           cb->env);
    });
}

void bench_camera_external(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    if (!cb->env.support.texture_images) {
        state.SkipWithError("no EGL_KHR_gl_texture_2D_image / external sampler here");
        return;
    }
    ecs::World& w = current->engine->world();
    gpu::Device& device = current->engine->device();
    auto made = device.create_texture(
        {.label = "bench camera frame", .width = camera_size.x, .height = camera_size.y});
    if (!made) {
        state.SkipWithError(made.error().message.c_str());
        return;
    }
    gpu::Texture source = std::move(made).value();
    source.upload(
        std::vector<std::byte>(static_cast<std::size_t>(camera_size.x) * camera_size.y * 4, std::byte{90}));
    auto image = device.create_external_image({.label = "bench camera image", .source = &source});
    if (!image) {
        state.SkipWithError(image.error().message.c_str());
        return;
    }
    (void)systems::upload_camera_frame(device, cb->image, cb->env);  // sizes the colour texture
    measure(state, device, [&] {
        cb->env.pending_import = &*image;
        cb->env.convert_due = true;
        systems::camera_environment_system(device, w.resource<Params>(), w.resource<systems::Environment>(),
                                           cb->env);
    });
    cb->env.pending_import = nullptr;
}

void bench_camera_mjpeg(benchmark::State& state) {
    // Fine diagonal stripes on a mid-grey frame: a fair stand-in for a webcam's MJPEG at quality 85.
    static std::vector<std::byte> jpeg;
    if (jpeg.empty()) {
        std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera_size.x) * camera_size.y * 3);
        const std::size_t stride = static_cast<std::size_t>(camera_size.x) * 3;
        for (std::size_t i = 0; i < rgb.size(); ++i)
            rgb[i] = static_cast<std::uint8_t>(((i % stride) * 7 + (i / stride) * 3) & 0xff);
        jpeg = camera::encode_jpeg(rgb, camera_size.x, camera_size.y, 85);
    }
    camera::MjpegDecoder decoder;
    for (auto _ : state) {
        auto r = decoder.decode(jpeg, camera_size.x, camera_size.y);
        if (!r) {
            state.SkipWithError(r.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(decoder.rgba().data());
    }
}

void print_camera_summary(const class Collector& c);

// Scenes and drop models (issue 5): a whole frame of each look at 1920x1080, chosen by the same --set
// lines an operator would write. Grid at 10 and 1000 drops/s (the goal: at most 10% more), analytic at
// 100 and 500 sources. Each run restores the default look, so the benchmarks above stay comparable.
struct Look {
    const char* name;
    std::vector<std::string> sets;
};
const std::vector<Look>& looks() {
    static const std::vector<Look> all{
        {"puddle_pulse", {}},
        {"puddle_scale_0.5", {"render.scale=0.5"}},
        {"puddle_image_ground", {"ground.checkerboard=false"}},
        {"puddle_grid_10", {"drops.model=grid", "grid.drops_per_second=10"}},
        {"puddle_grid_1000", {"drops.model=grid", "grid.drops_per_second=1000"}},
        {"puddle_analytic_100", {"drops.model=analytic", "analytic.sources=100"}},
        {"puddle_analytic_500", {"drops.model=analytic", "analytic.sources=500"}},
        {"ocean", {"scene.kind=ocean"}},
        {"street", {"scene.kind=street"}},
        {"street_rain", {"scene.kind=street", "overlay.rain=true"}},
    };
    return all;
}
constexpr glm::ivec2 look_size{1920, 1080};

void apply(Params& params, const std::vector<std::string>& sets) {
    for (const std::string& s : sets)
        if (auto a = params::parse_assignment(s))
            params.set(a->id, a->value, params::ParamSource::CommandLine);
}

void restore_default_look(Params& params) {
    const Params defaults;
    for (ParamId id : {ParamId::scene_kind, ParamId::drops_model, ParamId::overlay_rain,
                       ParamId::grid_drops_per_second, ParamId::analytic_sources, ParamId::render_scale,
                       ParamId::ground_checkerboard, ParamId::render_method})
        params.set(id, defaults.at(id), params::ParamSource::CommandLine);
}

void bench_look(benchmark::State& state, const Look& look) {
    Bench* b = bench_for(look_size, state);
    if (!b) return;
    restore_default_look(b->engine->params());  // the frame benchmarks before leave a method set
    apply(b->engine->params(), look.sets);
    std::string error;
    measure(state, b->engine->device(), [&] {
        if (auto r = b->engine->frame(1.0 / 60.0); !r) error = r.error().message;
    });
    restore_default_look(b->engine->params());
    if (!error.empty()) state.SkipWithError(error.c_str());
}

// The surface pass alone, where the drop models differ (the frame adds the same puddle render to each).
void bench_drop_pass(benchmark::State& state, const Look& look) {
    Bench* b = bench_for(look_size, state);
    if (!b) return;
    ecs::World& w = b->engine->world();
    gpu::Device& device = b->engine->device();
    Params& params = w.resource<Params>();
    apply(params, look.sets);
    auto& clock = w.resource<systems::FrameClock>();
    auto& surface = w.resource<systems::Surface>();
    measure(state, device, [&] {
        if (systems::selected_drop_model(params) == systems::DropModel::analytic)
            systems::analytic_ripple_system(device, params, clock, w.resource<systems::AnalyticRipples>(),
                                            surface);
        else if (systems::selected_drop_model(params) == systems::DropModel::grid)
            systems::grid_drop_system(device, params, clock, w.resource<systems::GridDrops>(), surface);
    });
    restore_default_look(params);
}

// Passes everything to the display reporter that the usual flags chose, and keeps ms per benchmark
// (by registered name; the mean over repetitions) for the summary.
class Collector : public benchmark::BenchmarkReporter {
public:
    explicit Collector(benchmark::BenchmarkReporter* display) : display_(display) {}
    bool ReportContext(const Context& context) override { return display_->ReportContext(context); }
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
            auto& [sum, n] = sums_[run.run_name.function_name];
            sum += run.GetAdjustedRealTime();  // in the benchmark's unit: ms
            ++n;
        }
        display_->ReportRuns(runs);
    }
    void Finalize() override { display_->Finalize(); }
    bool empty() const { return sums_.empty(); }
    std::optional<double> ms(const std::string& name) const {
        auto it = sums_.find(name);
        if (it == sums_.end()) return std::nullopt;
        return it->second.first / it->second.second;
    }

private:
    benchmark::BenchmarkReporter* display_;
    std::map<std::string, std::pair<double, int>> sums_;
};

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    int threads = 0;
    for (; std::getline(in, line);) {
        if (line.starts_with("processor")) ++threads;
        if (line.starts_with("model name") && model == "unknown CPU") model = line.substr(line.find(':') + 2);
    }
    return fmt::format("{} ({} threads)", model, threads);
}

// Other processes share llvmpipe's CPU cores: a loaded machine inflates every figure.
std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return fmt::format("{} {} {} (1, 5, 15 min)", one, five, fifteen);
}

std::string cell(std::optional<double> ms, std::optional<double> base) {
    if (!ms) return fmt::format("{:>20}", "-");
    return base ? fmt::format("{:>10.2f} {:>8.2f}x", *ms, *ms / *base)
                : fmt::format("{:>10.2f} {:>9}", *ms, "-");
}

void print_summary(const Collector& c) {
    std::printf("\nPuddle passes, ms (x floor of the same size)\n  GL:   %s\n  CPU:  %s\n  Load: %s\n\n%-20s",
                renderer.c_str(), cpu_model().c_str(), load_average().c_str(), "");
    for (glm::ivec2 s : sizes) std::printf("%20s", size_name(s).c_str());
    const std::string wave = fmt::format("wave_step/{}", Params{}.get<ParamId::wave_resolution>());
    for (const std::string& key :
         {std::string("floor"), wave, std::string("surface"), std::string("render/intersect"),
          std::string("render/raymarch"), std::string("frame/intersect"), std::string("frame/raymarch")}) {
        std::printf("\n%-20s", (key == wave ? key + " field" : key).c_str());
        for (glm::ivec2 s : sizes)  // the wave step is measured once, and set against each size's floor
            std::printf(
                "%s", cell(c.ms(key == wave ? wave : key + "/" + size_name(s)), c.ms("floor/" + size_name(s)))
                          .c_str());
    }
    for (const char* stage : {"render", "frame"}) {
        std::printf("\n%-20s", fmt::format("{} rm/int", stage).c_str());
        for (glm::ivec2 s : sizes) {
            const auto rm = c.ms(fmt::format("{}/raymarch/{}", stage, size_name(s)));
            const auto in = c.ms(fmt::format("{}/intersect/{}", stage, size_name(s)));
            std::printf(
                "%s", (rm && in ? fmt::format("{:>19.2f}x", *rm / *in) : fmt::format("{:>20}", "-")).c_str());
        }
    }
    std::printf("\n\nLooks at %s, ms per frame (x puddle_pulse); drop passes, ms\n",
                size_name(look_size).c_str());
    const auto pulse = c.ms("look/puddle_pulse");
    for (const Look& look : looks()) {
        std::printf("%-20s%s", look.name, cell(c.ms(fmt::format("look/{}", look.name)), pulse).c_str());
        if (look.sets.size() > 1 && look.sets[0].starts_with("drops."))
            std::printf("%s", cell(c.ms(fmt::format("drop_pass/{}", look.name)), std::nullopt).c_str());
        std::printf("\n");
    }
    for (const auto& [more, fewer] : {std::pair{"puddle_grid_1000", "puddle_grid_10"},
                                      std::pair{"puddle_analytic_500", "puddle_analytic_100"}}) {
        const auto a = c.ms(fmt::format("drop_pass/{}", more)), b = c.ms(fmt::format("drop_pass/{}", fewer));
        if (a && b) std::printf("%-20s%19.2fx  (drop pass, %s / %s)\n", "ratio", *a / *b, more, fewer);
    }
    print_camera_summary(c);
}

void print_camera_summary(const Collector& c) {
    std::printf("\nOne camera frame at %dx%d, ms\n", camera_size.x, camera_size.y);
    for (const char* key : {"camera/cpu_copy_yuyv", "camera/cpu_decode_mjpeg", "camera/gpu_convert_and_cube",
                            "camera/gpu_external_sampler"}) {
        const auto ms = c.ms(key);
        std::printf("%-30s%s\n", key,
                    ms ? fmt::format("{:>10.2f}", *ms).c_str() : fmt::format("{:>10}", "-").c_str());
    }
}

// The render shader's estimated per-pixel cost for one method: the variant the default parameters select
// (render/puddle_variant.hpp), with the default march steps.
bench::ShaderCost shader_cost(const char* method) {
    render::PuddleVariant v = render::choose_puddle_variant(Params{}, false);
    v.raymarch = std::string(method) == "raymarch";
    auto shader = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
    if (!shader) return {};
    return bench::estimate_shader_cost(shader->source, Params{}.get<ParamId::render_march_steps>());
}

Figures figures(const Collector& c) {
    Figures f;
    for (glm::ivec2 s : sizes) {
        const auto floor = c.ms("floor/" + size_name(s));
        for (const char* stage : {"render", "frame"})
            for (const char* m : methods)
                if (const auto ms = c.ms(fmt::format("{}/{}/{}", stage, m, size_name(s))); ms && floor)
                    f[fmt::format("{}/{}/{} x floor", stage, m, size_name(s))] = *ms / *floor;
        const auto rm = c.ms("render/raymarch/" + size_name(s)),
                   in = c.ms("render/intersect/" + size_name(s));
        if (rm && in) f[fmt::format("render/intersect/{} x raymarch", size_name(s))] = *in / *rm;
    }
    for (const char* m : methods) {
        const bench::ShaderCost cost = shader_cost(m);
        f[fmt::format("shader/{} texture fetches", m)] = cost.texture_fetches;
        f[fmt::format("shader/{} alu ops", m)] = cost.alu_ops;
    }
    return f;
}

// Prints the shader cost, then each figure beside its baseline; true when a shader cost regressed.
bool print_against_baseline(const Figures& now, const Figures& baseline, const std::string& path) {
    std::printf(
        "\nRender shader, estimated per pixel (longest path, from the source; bench/shader_cost.hpp)\n");
    for (const char* m : methods)
        std::printf("  %-10s %3.0f texture fetches, %4.0f ALU ops\n", m,
                    now.at(fmt::format("shader/{} texture fetches", m)),
                    now.at(fmt::format("shader/{} alu ops", m)));
    return check_baseline(now, baseline, path);
}

void register_all() {
    auto add = [](const std::string& name, auto fn) {
        benchmark::RegisterBenchmark(name.c_str(), fn)->UseRealTime()->Unit(benchmark::kMillisecond);
    };
    add("camera/cpu_copy_yuyv", bench_camera_copy);
    add("camera/cpu_decode_mjpeg", bench_camera_mjpeg);
    add("camera/gpu_convert_and_cube", bench_camera_gpu);
    add("camera/gpu_external_sampler", bench_camera_external);
    for (glm::ivec2 s : sizes) {
        const std::string n = size_name(s);
        add("floor/" + n, [s](benchmark::State& st) { bench_floor(st, s); });
        if (s == sizes[0])
            add(fmt::format("wave_step/{}", Params{}.get<ParamId::wave_resolution>()),
                [s](benchmark::State& st) { bench_wave_step(st, s); });
        add("surface/" + n, [s](benchmark::State& st) { bench_surface(st, s); });
        for (const char* m : methods)
            add(fmt::format("render/{}/{}", m, n), [s, m](benchmark::State& st) { bench_render(st, s, m); });
        for (const char* m : methods)
            add(fmt::format("frame/{}/{}", m, n), [s, m](benchmark::State& st) { bench_frame(st, s, m); });
    }
    // Start-up cost of the procedural night sky (CPU), which a board pays once.
    add("startup/night_sky_cubemap/256", [](benchmark::State& st) {
        for (auto _ : st) benchmark::DoNotOptimize(assets::night_sky_cubemap(256, 1));
    });
    for (const Look& look : looks()) {
        add(fmt::format("look/{}", look.name), [&look](benchmark::State& st) { bench_look(st, look); });
        if (look.sets.size() > 1 && look.sets[0].starts_with("drops."))
            add(fmt::format("drop_pass/{}", look.name),
                [&look](benchmark::State& st) { bench_drop_pass(st, look); });
    }
}

}  // namespace puddle::bench

int main(int argc, char** argv) {
    using namespace puddle::bench;
    spdlog::set_level(spdlog::level::warn);  // engine start-up logs would split the results table
    // Google Benchmark's 0.5 s default gives one or two iterations of a 1080p pass on llvmpipe; 2 s
    // steadies the figures and keeps the whole run near a minute. It goes first so a
    // --benchmark_min_time on the command line overrides it.
    static char default_min_time[] = "--benchmark_min_time=2";
    std::vector<char*> args{argv[0]};
    bool update_baseline = false;
    std::string baseline_path = PUDDLE_BENCH_BASELINE;
    for (int k = 1; k < argc; ++k) {  // our own flags; the rest are Google Benchmark's
        const std::string_view a = argv[k];
        if (a == "--update-baseline")
            update_baseline = true;
        else if (a.starts_with("--baseline="))
            baseline_path = std::string(a.substr(11));
        else
            args.push_back(argv[k]);
    }
    args.insert(args.begin() + 1, default_min_time);
    int args_count = static_cast<int>(args.size());
    benchmark::Initialize(&args_count, args.data());
    if (benchmark::ReportUnrecognizedArguments(args_count, args.data())) return 1;
    register_all();
    Collector collector(benchmark::CreateDefaultDisplayReporter());
    benchmark::RunSpecifiedBenchmarks(&collector);
    release_camera_bench();
    current.reset();  // GPU objects and the EGL context go before static destruction and driver teardown
    if (collector.empty()) {  // nothing ran: --benchmark_list_tests, a filter
        benchmark::Shutdown();
        return 0;
    }
    print_summary(collector);
    const Figures now = figures(collector);
    const bool regressed = print_against_baseline(now, read_baseline(baseline_path), baseline_path);
    if (update_baseline) {
        if (!write_baseline(baseline_path, now))
            std::fprintf(stderr, "puddle-bench: cannot write %s\n", baseline_path.c_str());
        else
            std::printf("\nBaseline written: %s\n", baseline_path.c_str());
    }
    benchmark::Shutdown();
    return regressed && !update_baseline ? 1 : 0;
}
