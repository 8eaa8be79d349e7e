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
// Every figure is taken on water in its steady state (bench/steady_state.hpp: rain runs until the field's
// RMS slope stops growing, a few hundred steps); frame_calm_start/ is the same frame one second after a
// calm start, a labelled extra.
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

#include <cstdio>
#include <string>
#include <vector>

#include "assets/procedural.hpp"
#include "bench/bench_engine.hpp"
#include "bench/bench_report.hpp"
#include "bench/camera_benchmarks.hpp"
#include "bench/look_benchmarks.hpp"
#include "bench/pass_benchmarks.hpp"

namespace puddle::bench {

void register_all() {
    register_camera_benchmarks();
    register_pass_benchmarks();
    // Start-up cost of the procedural night sky (CPU), which a board pays once.
    add_benchmark(
        fmt::format("startup/night_sky_cubemap/{}", assets::procedural_sky_face_size),
        [](benchmark::State& st) {
            for (auto _ : st)
                benchmark::DoNotOptimize(assets::night_sky_cubemap(assets::procedural_sky_face_size, 1));
        });
    register_look_benchmarks();
    register_calm_start_benchmarks();
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
    release_benches();  // GPU objects and the EGL context go before static destruction and driver teardown
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
