#include "bench/bench_report.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_engine.hpp"
#include "bench/camera_benchmarks.hpp"
#include "bench/look_benchmarks.hpp"
#include "bench/shader_cost.hpp"
#include "gpu/shader_source.hpp"
#include "render/puddle_variant.hpp"

namespace puddle::bench {

using params::ParamId;
using params::Params;

namespace {

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

}  // namespace

std::string cell(std::optional<double> ms, std::optional<double> base) {
    if (!ms) return fmt::format("{:>20}", "-");
    return base ? fmt::format("{:>10.2f} {:>8.2f}x", *ms, *ms / *base)
                : fmt::format("{:>10.2f} {:>9}", *ms, "-");
}

void print_summary(const Collector& c) {
    std::printf("\nPuddle passes, ms (x floor of the same size)\n  GL:   %s\n  CPU:  %s\n  Load: %s\n\n%-20s",
                renderer().c_str(), cpu_model().c_str(), load_average().c_str(), "");
    for (glm::ivec2 s : sizes) std::printf("%20s", size_name(s).c_str());
    const std::string wave = fmt::format("wave_step/{}", Params{}.get<ParamId::wave_resolution>());
    for (const std::string& key :
         {std::string("floor"), wave, std::string("surface"), std::string("render/intersect"),
          std::string("render/raymarch"), std::string("rain_overlay"), std::string("frame/intersect"),
          std::string("frame/raymarch")}) {
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
    std::printf("\n%-20s", "frame, calm start");
    for (glm::ivec2 s : sizes)  // x the steady-state frame
        std::printf("%s", cell(c.ms("frame_calm_start/intersect/" + size_name(s)),
                               c.ms("frame/intersect/" + size_name(s)))
                              .c_str());
    std::printf("\n\nWater: timed in its steady state (the calm-start row: x the steady frame)\n");
    for (const auto& [size, w] : warmups())
        std::printf("  %-10s %4d steps of rain, RMS slope %.5f per texel (calm start %.5f)%s\n",
                    size_name(size).c_str(), w.steps, w.steady_slope, w.calm_slope,
                    w.steady ? "" : "; still growing at the limit");
    print_look_summary(c);
    print_camera_summary(c);
}

namespace {

// The render shader's estimated per-pixel cost for one method: the variant the default parameters select
// (render/puddle_variant.hpp) under the procedural sky with its drifting clouds, with the default march
// steps.
bench::ShaderCost shader_cost(params::RenderMethod method) {
    render::PuddleVariant v = render::choose_puddle_variant(Params{}, false, true);
    v.raymarch = method == params::RenderMethod::raymarch;
    auto shader = gpu::assemble_shader("puddle.frag", render::variant_defines(v, false));
    if (!shader) return {};
    return bench::estimate_shader_cost(shader->source, Params{}.get<ParamId::render_march_steps>());
}

// The other looks' shaders, as their systems build them (systems/ocean, street, window, rain_overlay). Their
// loops run to named constants and uniforms the estimate cannot read, so each counts at most 8 trips (the
// ocean's octaves; its reference march of up to 200 steps as 8): a figure to compare runs by, not a
// per-pixel count.
constexpr int other_shader_loop_cap = 8;
struct OtherShader {
    const char* name;
    const char* file;
    std::vector<std::string> defines;
};
const std::vector<OtherShader>& other_shaders() {
    // The ocean's default is three passes: the heights and slopes at a quarter of the pixels (the map is
    // half the target's size per side), then the search that reads them.
    static const std::vector<OtherShader> all{{"ocean height map", "ocean.frag", {"OCEAN_HEIGHT_MAP"}},
                                              {"ocean heights", "ocean_height.frag", {}},
                                              {"ocean slopes", "ocean_slope.frag", {}},
                                              {"ocean secant", "ocean.frag", {"OCEAN_SECANT"}},
                                              {"ocean reference", "ocean.frag", {}},
                                              {"street", "street.frag", {}},
                                              {"window", "window.frag", {}},
                                              {"rain streaks", "rain_streaks.frag", {}}};
    return all;
}

}  // namespace

Figures figures(const Collector& c) {
    Figures f;
    for (glm::ivec2 s : sizes) {
        const auto floor = c.ms("floor/" + size_name(s));
        for (const char* stage : {"render", "frame"})
            for (params::RenderMethod m : methods)
                if (const auto ms =
                        c.ms(fmt::format("{}/{}/{}", stage, params::choice_name(m), size_name(s)));
                    ms && floor)
                    f[fmt::format("{}/{}/{} x floor", stage, params::choice_name(m), size_name(s))] =
                        *ms / *floor;
        const auto rm = c.ms("render/raymarch/" + size_name(s)),
                   in = c.ms("render/intersect/" + size_name(s));
        if (rm && in) f[fmt::format("render/intersect/{} x raymarch", size_name(s))] = *in / *rm;
    }
    if (const auto pulse = c.ms("look/puddle_pulse"))
        for (const std::string& name : c.names())
            if (name.starts_with("look/") && name != "look/puddle_pulse")
                if (const auto ms = c.ms(name)) f[name + " x puddle_pulse"] = *ms / *pulse;
    for (params::RenderMethod m : methods) {
        const bench::ShaderCost cost = shader_cost(m);
        f[fmt::format("shader/{} texture fetches", params::choice_name(m))] = cost.texture_fetches;
        f[fmt::format("shader/{} alu ops", params::choice_name(m))] = cost.alu_ops;
    }
    for (const OtherShader& o : other_shaders()) {
        auto shader = gpu::assemble_shader(o.file, o.defines);
        if (!shader) continue;
        const bench::ShaderCost cost = bench::estimate_shader_cost(shader->source, other_shader_loop_cap);
        f[fmt::format("shader/{} texture fetches", o.name)] = cost.texture_fetches;
        f[fmt::format("shader/{} alu ops", o.name)] = cost.alu_ops;
    }
    return f;
}

// Prints the shader cost, then each figure beside its baseline; true when a shader cost regressed.
bool print_against_baseline(const Figures& now, const Figures& baseline, const std::string& path) {
    std::printf(
        "\nRender shader, estimated per pixel (longest path, from the source; bench/shader_cost.hpp)\n");
    for (params::RenderMethod m : methods)
        std::printf("  %-10s %3.0f texture fetches, %4.0f ALU ops\n",
                    std::string(params::choice_name(m)).c_str(),
                    now.at(fmt::format("shader/{} texture fetches", params::choice_name(m))),
                    now.at(fmt::format("shader/{} alu ops", params::choice_name(m))));
    std::printf("The other looks' shaders (every loop counted at %d trips: to compare runs by)\n",
                other_shader_loop_cap);
    for (const OtherShader& o : other_shaders())
        if (now.contains(fmt::format("shader/{} alu ops", o.name)))
            std::printf("  %-16s %3.0f texture fetches, %5.0f ALU ops\n", o.name,
                        now.at(fmt::format("shader/{} texture fetches", o.name)),
                        now.at(fmt::format("shader/{} alu ops", o.name)));
    return check_baseline(now, baseline, path);
}

}  // namespace puddle::bench
