#pragma once
// `puddle --stats`: frame times and CPU time per frame in a fixed ring buffer, summarised every few
// seconds (fps, p50/p95/p99 frame time). Nothing here allocates after construction, so the frame loop
// stays allocation-free with --stats on (tests/app/frame_alloc_test.cpp).

#include <array>
#include <chrono>
#include <cstddef>
#include <optional>

namespace puddle::systems {

// Resident memory of this process from /proc/self/status, in KiB (0 where unreadable).
struct MemoryStatus {
    long rss_kib = 0;   // VmRSS: resident now
    long peak_kib = 0;  // VmHWM: the high-water mark
    long anon_kib = 0;  // RssAnon: heap, driver buffers (llvmpipe keeps textures here)
    long file_kib = 0;  // RssFile: pages of the binary and its shared libraries
};
MemoryStatus read_memory_status();

class FrameStats {
public:
    using clock = std::chrono::steady_clock;
    static constexpr std::size_t capacity = 1024;  // about 17 s at 60 fps; older frames drop out

    struct Summary {
        std::size_t frames = 0;
        double fps = 0;
        double p50_ms = 0, p95_ms = 0, p99_ms = 0, max_ms = 0;
        double cpu_ms = 0;       // process CPU per frame (every thread; on llvmpipe that includes rendering)
        double main_cpu_ms = 0;  // the frame loop's own thread per frame
    };

    explicit FrameStats(double report_every_s = 5.0);

    // Call once at the start of every frame: the time since the previous call is one frame.
    void tick();
    // One frame's sample, in seconds (tick() calls this; tests feed it directly).
    void add(double frame_s, double cpu_s, double main_cpu_s);
    // The frames since the last report, when report_every_s has passed since it; starts a new window.
    std::optional<Summary> take_report();
    // The frames in the current window.
    Summary summary() const;

private:
    struct Sample {
        double frame_s, cpu_s, main_cpu_s;
    };
    double report_every_s_;
    std::array<Sample, capacity> ring_{};
    mutable std::array<double, capacity> scratch_{};  // for the percentiles
    std::size_t next_ = 0, count_ = 0;
    bool started_ = false;
    clock::time_point last_tick_{};
    double last_cpu_s_ = 0, last_main_cpu_s_ = 0, window_s_ = 0;
};

}  // namespace puddle::systems
