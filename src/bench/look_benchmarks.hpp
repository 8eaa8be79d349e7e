#pragma once
// Scenes and drop models: a whole frame of each look at 1920x1080, chosen by the same --set lines an
// operator would write, and the surface pass alone where the drop models differ.

#include <glm/vec2.hpp>

#include "bench/bench_report.hpp"

namespace puddle::bench {

inline constexpr glm::ivec2 look_size{1920, 1080};

void register_look_benchmarks();
void print_look_summary(const Collector& c);

}  // namespace puddle::bench
