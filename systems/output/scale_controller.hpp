#pragma once
// The adaptive render scale's controller: a pure function of frame times, GPU times and a clock, so it is
// tested with synthetic loads (tests/systems/scale_controller_test.cpp). systems/output/adaptive_scale.hpp
// feeds it from the frame loop and hands its scale to the output canvas.
//
// How it decides. Samples are gathered for one window of `hold_s` seconds; at the end of each window the
// 90th percentile of the window's costs (GPU time per frame where timer queries give it, else the wall
// time per frame) is compared with the budget, 1 / target_fps:
// - above miss * budget, or a median above typical_miss * budget: the target is missed; the scale goes
//   down, by one to two steps toward the scale predicted to fit (cost taken as proportional to the pixels
//   shaded, scale squared);
// - else, when the cost predicted one step up (p90 * ((s + step) / s)^2) is below fit * budget, the scale
//   goes up one step. miss > 1 > fit is the hysteresis: a step down lands below the up threshold, a step
//   up lands below the down threshold, so a steady load never oscillates;
// - GPU times are the cost where timer queries give them, unless the window's median frame takes over
//   typical_miss * budget while their p90 reads under half of it: then the timer misses work (llvmpipe
//   runs a single pass's draws after the query ends) and the frame times are the cost from then on (the
//   timer would otherwise show headroom as soon as the frames fit, and the scale would go up and down);
// - frame times only, on a display that waits for vblank, a frame that fits shows as exactly one refresh
//   period and never shows headroom: after probe_after_s of meeting the target the scale tries a step up;
//   if the next window misses it goes back down and the wait before the next try doubles (at most
//   max_probe_after_s), so a scale at the edge moves at most once per that wait.
// At most one change per window: never more often than every hold_s seconds. A window after a change
// starts skip_after_change frames late (the canvas is remade, and GPU times arrive a few frames late).

#include <array>
#include <cstddef>
#include <optional>

namespace puddle::systems {

struct ScaleTuning {
    double target_fps = 60;      // > 0; the budget is 1 / target_fps seconds per frame
    double min_scale = 0.5;      // the lowest scale (render.min_scale)
    double max_scale = 1.0;      // the highest scale and the start (render.scale)
    double hold_s = 3.0;         // the decision window: at most one change per this many seconds
    double step = 0.05;          // a step up; a step down is one to two of these
    double miss = 1.10;          // p90 cost above miss * budget: the target is missed (1 frame in 10 late)
    double typical_miss = 1.02;  // or the median above this * budget: missed on average
    double pinned = 0.97;        // frame times only: a median at least this * budget may be vblank-bound
    double fit = 0.85;           // up when the p90 cost predicted one step up is below fit * budget
    double probe_after_s = 10;   // frame times only: meeting the target this long, try a step up
    double max_probe_after_s = 160;  // the longest wait between two tries that failed
    int skip_after_change = 3;       // frames not counted after a change
    double max_frame_s = 1.0;        // a longer frame is a stall (start-up, output off), not load: ignored
};

enum class CostSource { none, gpu, frame };

struct ScaleUpdate {
    float scale = 1;            // the scale for the next frame
    bool changed = false;       // differs from the previous frame's
    bool settled = false;       // the first window without a change after one or more changes (or at start)
    bool window_ended = false;  // a decision window ended with this frame
    // That window ran at the lowest scale (min_scale) and still missed the target: no scale holds it.
    bool short_at_floor = false;
};

class ScaleController {
public:
    explicit ScaleController(const ScaleTuning& tuning);

    // One frame that ended at now_s (seconds from any fixed epoch, never decreasing) and took frame_s
    // seconds of wall time since the previous one; gpu_s: the GPU time of a recent frame, when timer
    // queries gave one this frame. Never allocates.
    ScaleUpdate add_frame(double now_s, double frame_s, std::optional<double> gpu_s);

    float scale() const { return static_cast<float>(scale_); }
    const ScaleTuning& tuning() const { return tuning_; }
    // The last window's 90th-percentile cost in seconds, and what it was measured from.
    double last_cost_s() const { return last_cost_s_; }
    CostSource last_source() const { return last_source_; }

private:
    static constexpr std::size_t window_capacity = 512;  // the latest samples of a window
    struct Samples {
        std::array<double, window_capacity> values{};
        std::size_t count = 0, next = 0;
        void add(double v);
        void clear() { count = next = 0; }
        // The nearest-rank q-quantile (q in 0..1) of a window with samples; sorts a copy into scratch.
        double percentile(double q, std::array<double, window_capacity>& scratch) const;
    };
    void decide(double now_s, ScaleUpdate& update);

    ScaleTuning tuning_;
    double scale_;
    Samples gpu_, frame_;
    std::array<double, window_capacity> scratch_{};
    std::optional<double> window_start_;
    double last_change_s_ = 0;
    int skip_ = 0;
    bool unsettled_ = true;           // changes (or the start) not yet reported as settled
    bool timer_misses_work_ = false;  // GPU times read far under slow frames once: frame times from then on
    bool probing_ = false;            // the last change was a try up on frame times
    double probe_from_ = 0;           // the scale before that try
    double probe_after_s_;
    double last_cost_s_ = 0;
    CostSource last_source_ = CostSource::none;
};

}  // namespace puddle::systems
