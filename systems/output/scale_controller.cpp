#include "systems/output/scale_controller.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace puddle::systems {

void ScaleController::Samples::add(double v) {
    values[next] = v;
    next = (next + 1) % window_capacity;
    count = std::min(count + 1, window_capacity);
}

double ScaleController::Samples::percentile(double q, std::array<double, window_capacity>& scratch) const {
    std::copy_n(values.begin(), count, scratch.begin());
    const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(count - 1) + 0.5);  // nearest rank
    std::nth_element(scratch.begin(), scratch.begin() + k,
                     scratch.begin() + static_cast<std::ptrdiff_t>(count));
    return scratch[static_cast<std::size_t>(k)];
}

ScaleController::ScaleController(const ScaleTuning& tuning)
    : tuning_(tuning), scale_(tuning.max_scale), probe_after_s_(tuning.probe_after_s) {}

ScaleUpdate ScaleController::add_frame(double now_s, double frame_s, std::optional<double> gpu_s) {
    ScaleUpdate update{.scale = scale()};
    if (frame_s <= 0 || frame_s > tuning_.max_frame_s) return update;
    if (skip_ > 0) {
        --skip_;
        return update;
    }
    if (!window_start_) {
        window_start_ = now_s;
        if (last_change_s_ == 0) last_change_s_ = now_s;
    }
    frame_.add(frame_s);
    if (gpu_s && *gpu_s > 0) gpu_.add(*gpu_s);
    if (now_s - *window_start_ >= tuning_.hold_s) decide(now_s, update);
    return update;
}

void ScaleController::decide(double now_s, ScaleUpdate& update) {
    // GPU times measure the render alone and show headroom even when the display waits for vblank. But
    // frames that take well over the budget while the GPU time reads under half of them are not waiting
    // for vblank: the timer misses work (llvmpipe runs a pass's draws after the query has ended), so the
    // frame times decide.
    const double budget = 1.0 / tuning_.target_fps;
    const double frame_typical = frame_.count > 0 ? frame_.percentile(0.5, scratch_) : 0.0;
    if (gpu_.count > 0 && frame_typical > tuning_.typical_miss * budget &&
        gpu_.percentile(0.9, scratch_) < 0.5 * frame_typical)
        timer_misses_work_ = true;  // for good: a timer that reads short would later show false headroom
    const bool gpu = gpu_.count > 0 && !timer_misses_work_;
    const Samples& samples = gpu ? gpu_ : frame_;
    const double cost = samples.percentile(0.9, scratch_);
    const double typical = samples.percentile(0.5, scratch_);
    last_cost_s_ = cost;
    last_source_ = gpu ? CostSource::gpu : CostSource::frame;
    gpu_.clear();
    frame_.clear();
    window_start_.reset();

    const double s = scale_;
    double next = s;
    const bool was_probe = std::exchange(probing_, false);
    const bool missed = typical > tuning_.typical_miss * budget || cost > tuning_.miss * budget;
    update.window_ended = true;
    update.short_at_floor = missed && s <= tuning_.min_scale && !was_probe;
    if (missed && was_probe) {
        next = probe_from_;  // back to where it held
        probe_after_s_ = std::min(2 * probe_after_s_, tuning_.max_probe_after_s);
    } else if (missed && s > tuning_.min_scale) {
        // The scale whose predicted cost is fit * budget, reached in one or two steps.
        const double fitting = s * std::sqrt(tuning_.fit * budget / cost);
        const double down = std::clamp(s - fitting, tuning_.step, 2 * tuning_.step);
        next = std::max(tuning_.min_scale, s - down);
    } else if (!missed && s < tuning_.max_scale) {
        const double up = std::min(tuning_.max_scale, s + tuning_.step);
        const double predicted = cost * (up / s) * (up / s);
        // Frame times pinned at the budget: the display waits for vblank and hides any headroom.
        const bool pinned = typical >= tuning_.pinned * budget;
        const bool probe = !gpu && pinned && now_s - last_change_s_ >= probe_after_s_;
        if (predicted <= tuning_.fit * budget || probe) {
            next = up;
            probing_ = predicted > tuning_.fit * budget;
            probe_from_ = s;
        }
    }
    if (next != s) {
        scale_ = next;
        last_change_s_ = now_s;
        skip_ = tuning_.skip_after_change;
        unsettled_ = true;
        update.scale = scale();
        update.changed = true;
    } else if (unsettled_) {
        unsettled_ = false;
        update.settled = true;
    }
}

}  // namespace puddle::systems
