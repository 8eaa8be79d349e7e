#pragma once
// puddle-bench's summary: the milliseconds each benchmark took, as tables (x the floor pass of the same
// size), and the figures compared with the stored baseline (bench_baseline.hpp).

#include <benchmark/benchmark.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_baseline.hpp"

namespace puddle::bench {

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
    // Every benchmark measured, by registered name, in name order.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& [name, sum] : sums_) out.push_back(name);
        return out;
    }
    std::optional<double> ms(const std::string& name) const {
        auto it = sums_.find(name);
        if (it == sums_.end()) return std::nullopt;
        return it->second.first / it->second.second;
    }

private:
    benchmark::BenchmarkReporter* display_;
    std::map<std::string, std::pair<double, int>> sums_;
};

// A table cell: milliseconds and, when `base` is known, the ratio to it ("  12.34   2.10x").
std::string cell(std::optional<double> ms, std::optional<double> base);
// The tables of passes, looks and camera frames, with the GL renderer, CPU and load average.
void print_summary(const Collector& c);
// The ratios and shader costs the baseline keeps: each pass x the floor, each look x the default
// ("look/ocean x puddle_pulse", every look and drop model the run measured), the shader costs.
Figures figures(const Collector& c);
// Prints the shader cost, then each figure beside its baseline; true when a shader cost regressed.
bool print_against_baseline(const Figures& now, const Figures& baseline, const std::string& path);

}  // namespace puddle::bench
