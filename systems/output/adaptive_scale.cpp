#include "systems/output/adaptive_scale.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace puddle::systems {

using params::ParamId;

double resolved_target_fps(const params::Params& params, double display_refresh_hz) {
    const int target = params.get<ParamId::render_target_fps>();
    return target < 0 ? display_refresh_hz : static_cast<double>(target);
}

void gpu_timer_begin_system(AdaptiveScale& adaptive) {
    if (adaptive.controller) adaptive.timer.begin();
}

namespace {

const char* source_name(CostSource source) {
    return source == CostSource::gpu ? "GPU time" : "frame time";
}

// The controller for the parameters now; the old one is kept while they stay the same.
void follow_params(gpu::Device& device, const params::Params& params, AdaptiveScale& a) {
    const float render_scale = params.get<ParamId::render_scale>();
    a.target_fps = resolved_target_fps(params, a.display_refresh_hz);
    if (a.target_fps <= 0) {
        if (a.controller)
            spdlog::info("render: adaptive scale off; rendering at {:.2f}",
                         static_cast<double>(render_scale));
        a.controller.reset();
        a.timer.end();
        a.scale = render_scale;
        return;
    }
    ScaleTuning wanted = a.timing;
    wanted.target_fps = a.target_fps;
    wanted.max_scale = static_cast<double>(render_scale);
    wanted.min_scale =
        std::min(static_cast<double>(params.get<ParamId::render_min_scale>()), wanted.max_scale);
    if (a.controller) {
        const ScaleTuning& t = a.controller->tuning();
        if (t.target_fps == wanted.target_fps && t.max_scale == wanted.max_scale &&
            t.min_scale == wanted.min_scale && t.hold_s == wanted.hold_s)
            return;
    }
    if (!a.timer_made) {
        a.timer = device.create_gpu_timer();
        a.timer_made = true;
    }
    a.controller.emplace(wanted);
    a.scale = a.controller->scale();
    a.last_frame_s = -1;
    a.short_at_floor = a.short_at_floor_said = false;
    spdlog::info("render: adaptive scale on: {:g} fps, scale {:.2f} to {:.2f}, measured by {}", a.target_fps,
                 wanted.min_scale, wanted.max_scale,
                 a.timer.supported() ? "GPU timer queries" : "frame times (no GPU timer queries)");
}

}  // namespace

void adaptive_scale_system(gpu::Device& device, const params::Params& params, AdaptiveScale& a) {
    a.timer.end();
    follow_params(device, params, a);
    if (!a.controller) return;
    const std::optional<double> gpu_s = a.timer.read();
    const double now = a.clock();
    const double frame_s = a.last_frame_s < 0 ? 0 : now - a.last_frame_s;
    a.last_frame_s = now;
    const ScaleUpdate u = a.controller->add_frame(now, frame_s, gpu_s);
    a.scale = u.scale;
    if (u.window_ended) a.short_at_floor = u.short_at_floor;
    if (u.short_at_floor && !a.short_at_floor_said) {
        a.short_at_floor_said = true;
        const ScaleController& c = *a.controller;
        const double cost = c.last_cost_s(), budget = 1 / a.target_fps, floor = c.tuning().min_scale;
        // Cost goes with the pixels shaded, the scale squared (scale_controller.hpp).
        const double would_hold = floor * std::sqrt(c.tuning().fit * budget / cost);
        const std::string lower = would_hold >= 0.25
                                      ? fmt::format("render.min_scale to {:.2f}", would_hold)
                                      : std::string("render.min_scale cannot go low enough (0.25 at least)");
        spdlog::warn(
            "render: even the smallest scale cannot hold {:g} fps: at render.min_scale {:.2f} the p90 {} "
            "is {:.1f} ms a frame, about {:.0f} fps. Set render.target_fps to {:.0f} (what this GPU "
            "holds with this look), or lower {}, or choose a lighter look",
            a.target_fps, floor, source_name(c.last_source()), 1000 * cost, 1 / cost,
            std::max(1.0, std::floor(c.tuning().fit / cost)), lower);
    }
    if (u.settled) {
        const ScaleController& c = *a.controller;
        const double scale = static_cast<double>(c.scale());
        const bool floor = scale <= c.tuning().min_scale && scale < c.tuning().max_scale;
        spdlog::info(
            "render: adaptive scale settled at {:.2f} (p90 {} {:.1f} ms; target {:g} fps, {:.1f} ms){}",
            scale, source_name(c.last_source()), 1000 * c.last_cost_s(), a.target_fps, 1000 / a.target_fps,
            floor ? "; at render.min_scale" : "");
    }
}

}  // namespace puddle::systems
