#pragma once
// The floor, wave step, surface, render and whole-frame benchmarks at each size of bench_engine.hpp, on
// water warmed to its steady state.

namespace puddle::bench {

void register_pass_benchmarks();
// The whole frame (intersect) from a calm start, the figure before the steady state: registered last, as
// it makes its engines again.
void register_calm_start_benchmarks();

}  // namespace puddle::bench
