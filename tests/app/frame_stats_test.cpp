// `--stats` figures (systems/common/frame_stats.hpp): nearest-rank percentiles, fps and CPU per frame over
// the frames of a window, a report only once the window is long enough, and the ring forgetting the oldest
// frames past its capacity.
#include "systems/common/frame_stats.hpp"

#include <gtest/gtest.h>

namespace puddle::app {
namespace {

// Frames of 1..100 ms (in a shuffled order: the percentiles must not depend on it), CPU half the frame.
TEST(FrameStats, PercentilesByNearestRankAndMeansPerFrame) {
    systems::FrameStats stats(1e9);
    for (int i = 0; i < 100; ++i) {
        const double ms = (i * 37) % 100 + 1;  // 37 is prime to 100: every value once
        stats.add(ms / 1000, ms / 2000, ms / 4000);
    }
    const systems::FrameStats::Summary s = stats.summary();
    EXPECT_EQ(s.frames, 100u);
    // Rank round(q * 99) of the sorted values 1..100 is value rank + 1.
    EXPECT_DOUBLE_EQ(s.p50_ms, 51);  // round(49.5) = 50
    EXPECT_DOUBLE_EQ(s.p95_ms, 95);  // round(94.05) = 94
    EXPECT_DOUBLE_EQ(s.p99_ms, 99);  // round(98.01) = 98
    EXPECT_DOUBLE_EQ(s.max_ms, 100);
    const double mean_ms = 50.5;
    EXPECT_NEAR(s.fps, 1000 / mean_ms, 1e-9);
    EXPECT_NEAR(s.cpu_ms, mean_ms / 2, 1e-9);
    EXPECT_NEAR(s.main_cpu_ms, mean_ms / 4, 1e-9);
}

TEST(FrameStats, ReportsOnceTheWindowIsLongEnoughThenStartsAgain) {
    systems::FrameStats stats(1.0);
    for (int i = 0; i < 59; ++i) stats.add(1.0 / 60, 0, 0);
    EXPECT_FALSE(stats.take_report()) << "59/60 s is not a whole second";
    stats.add(2.0 / 60, 0, 0);
    const auto report = stats.take_report();
    ASSERT_TRUE(report);
    EXPECT_EQ(report->frames, 60u);
    EXPECT_NEAR(report->fps, 60 / (61.0 / 60), 1e-9);
    EXPECT_EQ(stats.summary().frames, 0u) << "a new window";
    EXPECT_FALSE(stats.take_report());
}

// Past the capacity the oldest frames drop out: 10 slow frames then `capacity` fast ones leave only the
// fast ones.
TEST(FrameStats, TheRingKeepsTheLatestFramesOnly) {
    systems::FrameStats stats(1e9);
    for (int i = 0; i < 10; ++i) stats.add(1.0, 0, 0);
    for (std::size_t i = 0; i < systems::FrameStats::capacity; ++i) stats.add(0.010, 0, 0);
    const systems::FrameStats::Summary s = stats.summary();
    EXPECT_EQ(s.frames, systems::FrameStats::capacity);
    EXPECT_DOUBLE_EQ(s.max_ms, 10);
    EXPECT_NEAR(s.fps, 100, 1e-6);
}

TEST(FrameStats, NoFramesNoFigures) {
    systems::FrameStats stats(0);
    EXPECT_EQ(stats.summary().frames, 0u);
    EXPECT_EQ(stats.summary().fps, 0);
    EXPECT_FALSE(stats.take_report()) << "nothing to report even when the window has passed";
}

TEST(MemoryStatus, ReadsThisProcesssResidentMemory) {
    const systems::MemoryStatus m = systems::read_memory_status();
    EXPECT_GT(m.rss_kib, 0);
    EXPECT_GE(m.peak_kib, m.rss_kib) << "the high-water mark is at least what is resident now";
    EXPECT_GT(m.file_kib, 0) << "the test binary's own pages";
}

}  // namespace
}  // namespace puddle::app
