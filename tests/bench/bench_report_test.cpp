// puddle-bench's summary (bench/bench_report.hpp) on hand-made benchmark runs: the Collector keeps the mean
// of each benchmark's repetitions in ms (aggregates and failed runs left out) and passes every run on to
// the display reporter; a table cell's ms and ratio; figures() makes the ratios the baseline keeps from
// exactly the runs there are, plus the render shader's cost for each method; print_against_baseline says
// whether a shader cost rose.
#include "bench/bench_report.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace puddle::bench {
namespace {

using Run = benchmark::BenchmarkReporter::Run;

// The display reporter the usual flags would choose: records the names it was given.
class RecordingReporter : public benchmark::BenchmarkReporter {
public:
    std::vector<std::string> names;
    int finalized = 0;
    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) names.push_back(r.run_name.function_name);
    }
    void Finalize() override { ++finalized; }
};

// One repetition of `name` that took `ms` per iteration (over 4 iterations, as Google Benchmark reports).
Run run(const std::string& name, double ms) {
    Run r;
    r.run_name.function_name = name;
    r.time_unit = benchmark::kMillisecond;
    r.iterations = 4;
    r.real_accumulated_time = ms * 4 / 1000.0;  // seconds, over all iterations
    return r;
}

Run failed(const std::string& name) {
    Run r = run(name, 1000);
    r.error_occurred = true;
    r.error_message = "no engine";
    return r;
}

Run aggregate(const std::string& name, double ms) {
    Run r = run(name, ms);
    r.run_type = Run::RT_Aggregate;
    r.aggregate_name = "mean";
    return r;
}

TEST(BenchReport, TheCollectorKeepsTheMeanOfTheRepetitionsAndPassesEveryRunOn) {
    RecordingReporter display;
    Collector c(&display);
    EXPECT_TRUE(c.empty());
    c.ReportRuns({run("floor/1280x720", 2.0), run("floor/1280x720", 4.5), aggregate("floor/1280x720", 99.0)});
    c.ReportRuns({failed("surface/1280x720"), run("surface/1920x1080", 0.25)});
    c.Finalize();
    EXPECT_FALSE(c.empty());
    EXPECT_DOUBLE_EQ(c.ms("floor/1280x720").value(), 3.25) << "(2 + 4.5) / 2; the aggregate is no repetition";
    EXPECT_DOUBLE_EQ(c.ms("surface/1920x1080").value(), 0.25);
    EXPECT_FALSE(c.ms("surface/1280x720").has_value()) << "a failed run has no time";
    EXPECT_FALSE(c.ms("floor/1920x1080").has_value());
    EXPECT_EQ(display.names, (std::vector<std::string>{"floor/1280x720", "floor/1280x720", "floor/1280x720",
                                                       "surface/1280x720", "surface/1920x1080"}));
    EXPECT_EQ(display.finalized, 1);
}

TEST(BenchReport, ACellIsTwentyCharactersOfMsAndRatio) {
    EXPECT_EQ(cell(12.5, 5.0), "     12.50     2.50x");
    EXPECT_EQ(cell(0.25, std::nullopt), "      0.25         -");
    EXPECT_EQ(cell(std::nullopt, 5.0), std::string(19, ' ') + "-");
}

TEST(BenchReport, FiguresAreRatiosOfTheRunsThereAreAndTheShaderCosts) {
    RecordingReporter display;
    Collector c(&display);
    c.ReportRuns({run("floor/1280x720", 2.0), run("render/intersect/1280x720", 3.0),
                  run("render/raymarch/1280x720", 6.0), run("frame/intersect/1280x720", 4.0),
                  // No floor at 1920x1080: only the intersect/raymarch ratio can be made there.
                  run("render/intersect/1920x1080", 5.0), run("render/raymarch/1920x1080", 20.0)});
    const Figures f = figures(c);
    std::set<std::string> timing;
    for (const auto& [name, value] : f)
        if (!name.starts_with("shader/")) timing.insert(name);
    EXPECT_EQ(timing, (std::set<std::string>{
                          "render/intersect/1280x720 x floor", "render/raymarch/1280x720 x floor",
                          "frame/intersect/1280x720 x floor", "render/intersect/1280x720 x raymarch",
                          "render/intersect/1920x1080 x raymarch"}));
    EXPECT_DOUBLE_EQ(f.at("render/intersect/1280x720 x floor"), 1.5);
    EXPECT_DOUBLE_EQ(f.at("render/raymarch/1280x720 x floor"), 3.0);
    EXPECT_DOUBLE_EQ(f.at("frame/intersect/1280x720 x floor"), 2.0);
    EXPECT_DOUBLE_EQ(f.at("render/intersect/1280x720 x raymarch"), 0.5);
    EXPECT_DOUBLE_EQ(f.at("render/intersect/1920x1080 x raymarch"), 0.25);

    // The shader costs come from the source, not the runs: present for both methods whatever ran, and the
    // ray-march reads the height field once per step where intersect refines in one or two.
    for (const char* key : {"shader/intersect texture fetches", "shader/intersect alu ops",
                            "shader/raymarch texture fetches", "shader/raymarch alu ops"})
        EXPECT_GT(f.count(key) ? f.at(key) : 0.0, 0.0) << key;
    EXPECT_GT(f.at("shader/raymarch texture fetches"), f.at("shader/intersect texture fetches"));
    Collector none(&display);
    const Figures costs_only = figures(none);
    EXPECT_EQ(costs_only.size(), 4u + 2u * 8u)
        << "the puddle's two methods and the other looks' eight shaders";
    for (const char* look : {"ocean height map", "ocean heights", "ocean slopes", "ocean secant",
                             "ocean reference", "street", "window", "rain streaks"})
        EXPECT_GT(costs_only.at(fmt::format("shader/{} alu ops", look)), 0.0) << look;
    EXPECT_EQ(costs_only.at("shader/raymarch alu ops"), f.at("shader/raymarch alu ops"));
}

// Every look and drop model the run measured, as a ratio to the default look in the same run; none
// without the default's row.
TEST(BenchReport, EachLookIsARatioToTheDefaultInTheSameRun) {
    RecordingReporter display;
    Collector c(&display);
    c.ReportRuns(
        {run("look/puddle_pulse", 100.0), run("look/ocean", 180.0), run("look/puddle_grid_10", 50.0)});
    const Figures f = figures(c);
    EXPECT_DOUBLE_EQ(f.at("look/ocean x puddle_pulse"), 1.8);
    EXPECT_DOUBLE_EQ(f.at("look/puddle_grid_10 x puddle_pulse"), 0.5);
    EXPECT_EQ(f.count("look/puddle_pulse x puddle_pulse"), 0u);
    Collector without_default(&display);
    without_default.ReportRuns({run("look/ocean", 180.0)});
    EXPECT_EQ(figures(without_default).count("look/ocean x puddle_pulse"), 0u);
}

TEST(BenchReport, AgainstTheBaselineARiseInAShaderCostIsARegression) {
    RecordingReporter display;
    Collector c(&display);
    const Figures now = figures(c);
    const std::string path = "bench_baseline.json";
    EXPECT_FALSE(print_against_baseline(now, now, path)) << "the same costs";
    Figures cheaper = now;
    cheaper["shader/intersect texture fetches"] -= 1;
    EXPECT_TRUE(print_against_baseline(now, cheaper, path)) << "the shader now reads one texture more";
    Figures dearer = now;
    dearer["shader/raymarch alu ops"] += 10;
    EXPECT_FALSE(print_against_baseline(now, dearer, path)) << "a cost that fell is no regression";
}

}  // namespace
}  // namespace puddle::bench
