// puddle-bench's stored baseline (bench/bench_baseline.hpp): figures written and read back, a filtered run
// keeping the figures it did not make, and which rises fail a build (shader costs) and which only warn
// (timing ratios).
#include "bench/bench_baseline.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/test_support.hpp"

namespace puddle::bench {
namespace {

TEST(BenchBaseline, AMissingFileIsAnEmptyBaseline) {
    test::TempDir dir;
    EXPECT_TRUE(read_baseline((dir / "none.json").string()).empty());
}

// Fails if write_baseline replaced the file with only this run's figures.
TEST(BenchBaseline, WrittenFiguresReadBackAndAFilteredRunKeepsTheOthers) {
    test::TempDir dir;
    const std::string path = (dir / "baseline.json").string();
    ASSERT_TRUE(write_baseline(path, {{"shader/puddle", 412.0}, {"ratio/ocean", 3.25}}));
    EXPECT_EQ(read_baseline(path), (Figures{{"shader/puddle", 412.0}, {"ratio/ocean", 3.25}}))
        << "the \"_about\" text is no figure";
    ASSERT_TRUE(write_baseline(path, {{"ratio/ocean", 2.5}, {"ratio/street", -1.125}}));
    EXPECT_EQ(read_baseline(path),
              (Figures{{"shader/puddle", 412.0}, {"ratio/ocean", 2.5}, {"ratio/street", -1.125}}));
}

// What check_baseline prints (to stdout) and returns.
struct Check {
    bool regressed;
    std::string printed;
};
Check check(const Figures& now, const Figures& baseline) {
    std::fflush(stdout);
    testing::internal::CaptureStdout();
    const bool regressed = check_baseline(now, baseline, "baseline.json");
    std::fflush(stdout);
    return {regressed, testing::internal::GetCapturedStdout()};
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A shader cost is exact: half an operation more is a regression. A ratio may drift 25% with the machine's
// load, and even past that it only warns.
TEST(BenchBaseline, OnlyARisingShaderCostIsARegression) {
    const Figures baseline{{"shader/puddle", 400.0}, {"ratio/ocean", 2.0}};
    EXPECT_FALSE(check({{"shader/puddle", 400.4}, {"ratio/ocean", 2.4}}, baseline).regressed);
    const Check cost = check({{"shader/puddle", 401.0}}, baseline);
    EXPECT_TRUE(cost.regressed);
    EXPECT_TRUE(has(cost.printed, "REGRESSION")) << cost.printed;
    const Check slow = check({{"ratio/ocean", 2.6}, {"ratio/new", 1.0}}, baseline);
    EXPECT_FALSE(slow.regressed) << "timings only warn";
    EXPECT_TRUE(has(slow.printed, "REGRESSION")) << slow.printed;
    EXPECT_TRUE(has(slow.printed, "(no baseline)")) << slow.printed;
    const Check fast = check({{"ratio/ocean", 1.5}}, baseline);
    EXPECT_TRUE(has(fast.printed, "better")) << fast.printed;
    EXPECT_FALSE(fast.regressed);
}

}  // namespace
}  // namespace puddle::bench
