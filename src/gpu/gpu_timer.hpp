#pragma once
// The GPU time of a span of passes (a frame), from GL_EXT_disjoint_timer_query, read without waiting:
// a small ring of GL_TIME_ELAPSED_EXT queries, each read a few frames after it ended, once the GPU says
// its result is there. A result over a disjoint event (GL_GPU_DISJOINT_EXT: a clock change, a context
// switch on some drivers) is thrown away, as the extension asks. Made by Device::create_gpu_timer.

#include <array>
#include <cstdint>
#include <optional>

#include "gpu/handle.hpp"

namespace puddle::gpu {

namespace detail {
void delete_query(std::uint32_t id);
}

class GpuTimer {
public:
    static constexpr int depth = 4;  // frames in flight before a query is read (drivers queue 2 to 3)

    GpuTimer() = default;  // measures nothing: supported() is false
    // Whether the context has timer queries; without them begin() and end() do nothing and read() is empty.
    bool supported() const { return static_cast<bool>(queries_[0]); }
    // Starts timing the passes that follow. Only one span at a time (GL allows one active time query);
    // a span is skipped while every query of the ring still waits for its result.
    void begin();
    // Ends the span begun by begin().
    void end();
    // The GPU time of the oldest span whose result has come, in seconds; empty when none has. Never waits.
    std::optional<double> read();

private:
    friend class Device;
    std::array<GlHandle<detail::delete_query>, depth> queries_;
    std::array<bool, depth> pending_{};  // ended, result not read yet
    int next_ = 0;                       // the query the next begin() uses
    int oldest_ = 0;                     // the pending query read() looks at
    bool active_ = false;
};

}  // namespace puddle::gpu
