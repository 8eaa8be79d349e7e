#pragma once
// What one 1280x720 camera frame costs: the CPU copy or MJPEG decode, the GPU conversion into the cube,
// and the external sampler (systems/sky/camera_environment.hpp).

#include "bench/bench_report.hpp"

namespace puddle::bench {

void register_camera_benchmarks();
// Its GPU objects belong to the current engine's context: released before that engine (bench_engine).
void release_camera_bench();
void print_camera_summary(const Collector& c);

}  // namespace puddle::bench
