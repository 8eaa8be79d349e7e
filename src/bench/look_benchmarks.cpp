#include "bench/look_benchmarks.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_engine.hpp"
#include "params/config_loader.hpp"
#include "systems/analytic_ripples/analytic_ripple_system.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/shown_look.hpp"
#include "systems/grid_drops/grid_drop_system.hpp"
#include "systems/water/surface_system.hpp"

namespace puddle::bench {

using params::ParamId;
using params::Params;

namespace {

// Scenes and drop models: a whole frame of each look at 1920x1080, chosen by the same --set
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
        // The old default's ground (the paving may cost at most 10% more than this).
        {"puddle_checkerboard", {"ground.checkerboard=true"}},
        {"puddle_grid_10", {"drops.model=grid", "grid.drops_per_second=10"}},
        {"puddle_grid_1000", {"drops.model=grid", "grid.drops_per_second=1000"}},
        {"puddle_analytic_100", {"drops.model=analytic", "analytic.sources=100"}},
        {"puddle_analytic_500", {"drops.model=analytic", "analytic.sources=500"}},
        {"ocean", {"scene.kind=ocean"}},
        {"ocean_secant", {"scene.kind=ocean", "ocean.method=secant"}},
        {"ocean_reference", {"scene.kind=ocean", "ocean.method=reference"}},
        {"street", {"scene.kind=street"}},
        {"street_rain", {"scene.kind=street", "overlay.rain=true"}},
        {"window", {"scene.kind=window"}},
        // Where the default's time goes: without its streaks, within the reference's box.
        {"puddle_no_streaks", {"overlay.rain=false"}},
        {"puddle_box", {"puddle.shape=box"}},
        // Last, as they make a new field (the rows above see the default's field in its steady state): the
        // reference's field under the default look, and the default look before the picture work (the
        // reference's 512 field and box, the setts, no streaks), which the default is held to 1.3 times.
        {"puddle_reference_field", {"wave.model=reference", "wave.resolution=512"}},
        {"puddle_before_the_picture",
         {"wave.model=reference", "wave.resolution=512", "puddle.shape=box", "overlay.rain=false"}},
    };
    return all;
}

void apply(Params& params, const std::vector<std::string>& sets) {
    for (const std::string& s : sets)
        if (auto a = params::parse_assignment(s))
            params.set(a->id, a->value, params::ParamSource::CommandLine);
}

// Every parameter any look sets, and the method the frame benchmarks set, back to its default.
void restore_default_look(Params& params) {
    const Params defaults;
    params.set(ParamId::render_method, defaults.at(ParamId::render_method), params::ParamSource::CommandLine);
    for (const Look& look : looks())
        for (const std::string& s : look.sets)
            if (auto a = params::parse_assignment(s))
                params.set(a->id, defaults.at(a->id), params::ParamSource::CommandLine);
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

}  // namespace

void register_look_benchmarks() {
    for (const Look& look : looks()) {
        add_benchmark(fmt::format("look/{}", look.name),
                      [&look](benchmark::State& st) { bench_look(st, look); });
        if (look.sets.size() > 1 && look.sets[0].starts_with("drops."))
            add_benchmark(fmt::format("drop_pass/{}", look.name),
                          [&look](benchmark::State& st) { bench_drop_pass(st, look); });
    }
}

void print_look_summary(const Collector& c) {
    std::printf("\nLooks at %s, ms per frame (x puddle_pulse); drop passes, ms\n",
                size_name(look_size).c_str());
    const auto pulse = c.ms("look/puddle_pulse");
    for (const Look& look : looks()) {
        std::printf("%-20s%s", look.name, cell(c.ms(fmt::format("look/{}", look.name)), pulse).c_str());
        if (look.sets.size() > 1 && look.sets[0].starts_with("drops."))
            std::printf("%s", cell(c.ms(fmt::format("drop_pass/{}", look.name)), std::nullopt).c_str());
        std::printf("\n");
    }
    if (const auto before = c.ms("look/puddle_before_the_picture"); before && pulse)
        std::printf("%-20s%19.2fx  (the default / the default before the picture; the goal: at most 1.3)\n",
                    "picture cost", *pulse / *before);
    for (const auto& [more, fewer] : {std::pair{"puddle_grid_1000", "puddle_grid_10"},
                                      std::pair{"puddle_analytic_500", "puddle_analytic_100"}}) {
        const auto a = c.ms(fmt::format("drop_pass/{}", more)), b = c.ms(fmt::format("drop_pass/{}", fewer));
        if (a && b) std::printf("%-20s%19.2fx  (drop pass, %s / %s)\n", "ratio", *a / *b, more, fewer);
    }
}

}  // namespace puddle::bench
