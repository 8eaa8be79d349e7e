#pragma once
// The floor, wave step, surface, render and whole-frame benchmarks at each size of bench_engine.hpp.

namespace puddle::bench {

void register_pass_benchmarks();

}  // namespace puddle::bench
