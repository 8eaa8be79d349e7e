#pragma once
// puddle-bench's stored baseline (src/bench/bench_baseline.json): ratios to the floor pass (or to raymarch)
// and the render shader's estimated cost, by name, never milliseconds. A ratio only warns when it rises
// (one run on a shared machine can be off by half); a shader cost is exact, so its rise is a regression.

#include <map>
#include <string>

namespace puddle::bench {

using Figures = std::map<std::string, double>;

// A flat JSON object of names and numbers, as write_baseline makes it; empty when the file is missing.
Figures read_baseline(const std::string& path);
// Writes `f` over the file, keeping the figures it holds that `f` lacks (a filtered run).
bool write_baseline(const std::string& path, Figures f);
// Prints each figure beside its baseline; true when a shader cost ("shader/...") regressed.
bool check_baseline(const Figures& now, const Figures& baseline, const std::string& path);

}  // namespace puddle::bench
