#include "systems/synced_changes.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <ctime>

namespace puddle::systems {

using params::ParamId;

namespace {

// "12:00:02.000 UTC".
std::string utc_text(std::int64_t ns) {
    const std::time_t s = static_cast<std::time_t>(ns / ns_per_second);
    tm t{};
    gmtime_r(&s, &t);
    char text[32];
    const std::size_t n = std::strftime(text, sizeof text, "%H:%M:%S", &t);
    return fmt::format("{}.{:03} UTC", std::string_view(text, n), (ns % ns_per_second) / 1'000'000);
}

}  // namespace

void synced_changes_system(const WallClock& wall, const FrameClock& clock, const OutputPower& power,
                           LiveTuning& tuning, params::Params& params, WallSteps& steps) {
    if (!tuning.layers_changed) return;
    if (steps.change_step == 0) {
        const std::int64_t at = tuning.apply_at_ns.value_or(
            change_boundary(wall.now_ns(), params.get<ParamId::wall_change_period>()));
        const double rate = params.get<ParamId::wave_steps_per_second>();
        steps.change_step = static_cast<std::uint64_t>(std::max<std::int64_t>(1, step_at(at, rate)));
        spdlog::info("{}: applies at {} (step {}), with the wall", tuning.change_reason, utc_text(at),
                     steps.change_step);
    }
    const bool due = power.on ? clock.step_index + 1 >= steps.change_step
                              : step_at(wall.now_ns(), params.get<ParamId::wave_steps_per_second>()) >=
                                    static_cast<std::int64_t>(steps.change_step);
    if (!due) return;
    steps.change_step = 0;
    tuning.apply_at_ns.reset();
    tuning.layers_changed = false;
    apply_layers(tuning, params, tuning.change_reason);
}

}  // namespace puddle::systems
