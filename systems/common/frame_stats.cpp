#include "systems/common/frame_stats.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace puddle::systems {

namespace {

double cpu_seconds(clockid_t id) {
    timespec ts{};
    clock_gettime(id, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

}  // namespace

MemoryStatus read_memory_status() {
    MemoryStatus m;
    FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return m;
    char line[256];
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, "VmRSS:", 6) == 0) m.rss_kib = std::strtol(line + 6, nullptr, 10);
        if (std::strncmp(line, "VmHWM:", 6) == 0) m.peak_kib = std::strtol(line + 6, nullptr, 10);
        if (std::strncmp(line, "RssAnon:", 8) == 0) m.anon_kib = std::strtol(line + 8, nullptr, 10);
        if (std::strncmp(line, "RssFile:", 8) == 0) m.file_kib = std::strtol(line + 8, nullptr, 10);
    }
    std::fclose(f);
    return m;
}

FrameStats::FrameStats(double report_every_s) : report_every_s_(report_every_s) {}

void FrameStats::tick() {
    const auto now = clock::now();
    const double cpu = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID), main_cpu = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
    if (started_)
        add(std::chrono::duration<double>(now - last_tick_).count(), cpu - last_cpu_s_,
            main_cpu - last_main_cpu_s_);
    started_ = true;
    last_tick_ = now;
    last_cpu_s_ = cpu;
    last_main_cpu_s_ = main_cpu;
}

void FrameStats::add(double frame_s, double cpu_s, double main_cpu_s) {
    ring_[next_] = {frame_s, cpu_s, main_cpu_s};
    next_ = (next_ + 1) % capacity;
    count_ = std::min(count_ + 1, capacity);
    window_s_ += frame_s;
}

FrameStats::Summary FrameStats::summary() const {
    Summary s;
    s.frames = count_;
    if (count_ == 0) return s;
    double cpu = 0, main_cpu = 0, frame = 0;
    for (std::size_t k = 0; k < count_; ++k) {
        const Sample& x = ring_[(next_ + capacity - count_ + k) % capacity];
        scratch_[k] = x.frame_s;
        frame += x.frame_s;
        cpu += x.cpu_s;
        main_cpu += x.main_cpu_s;
    }
    const auto first = scratch_.begin(), last = scratch_.begin() + static_cast<std::ptrdiff_t>(count_);
    std::sort(first, last);
    auto at = [&](double q) {  // nearest rank
        const auto k = static_cast<std::size_t>(q * static_cast<double>(count_ - 1) + 0.5);
        return 1000.0 * scratch_[k];
    };
    s.p50_ms = at(0.50);
    s.p95_ms = at(0.95);
    s.p99_ms = at(0.99);
    s.max_ms = 1000.0 * scratch_[count_ - 1];
    s.fps = frame > 0 ? static_cast<double>(count_) / frame : 0;
    s.cpu_ms = 1000.0 * cpu / static_cast<double>(count_);
    s.main_cpu_ms = 1000.0 * main_cpu / static_cast<double>(count_);
    return s;
}

std::optional<FrameStats::Summary> FrameStats::take_report() {
    if (window_s_ < report_every_s_ || count_ == 0) return std::nullopt;
    const Summary s = summary();
    count_ = 0;
    window_s_ = 0;
    return s;
}

}  // namespace puddle::systems
