#include "systems/tuning/synced_changes.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <ctime>

namespace puddle::systems {

using params::ParamId;

namespace {

// "12:00:02.000 UTC"; with the date when it is not today's.
std::string utc_text(std::int64_t ns, std::int64_t now_ns) {
    const std::time_t s = static_cast<std::time_t>(ns / ns_per_second);
    const bool today = ns / ns_per_second / 86400 == now_ns / ns_per_second / 86400;
    tm t{};
    gmtime_r(&s, &t);
    char text[32];
    const std::size_t n = std::strftime(text, sizeof text, today ? "%H:%M:%S" : "%Y-%m-%d %H:%M:%S", &t);
    return fmt::format("{}.{:03} UTC", std::string_view(text, n), (ns % ns_per_second) / 1'000'000);
}

// Where a change lands: a remote message's apply_at when it is ahead, but not by more than
// max_apply_ahead_ns (a mistyped time would hold this and every later change); otherwise the boundary.
std::int64_t change_time(const PendingChange& change, std::int64_t now, std::int64_t boundary) {
    if (!change.apply_at_ns) return boundary;
    const std::int64_t asked = *change.apply_at_ns;
    if (asked >= now && asked - now <= max_apply_ahead_ns) return asked;
    spdlog::warn("{}: apply_at {} is {}: applied with the wall at {} instead", change.reason,
                 utc_text(asked, now), asked < now ? "past" : "more than an hour ahead",
                 utc_text(boundary, now));
    return boundary;
}

}  // namespace

void synced_changes_system(const WallClock& wall, const FrameClock& clock, const OutputPower& power,
                           LiveTuning& tuning, params::Params& params, WallSteps& steps) {
    const std::optional<PendingChange> change = pending_change(tuning);
    if (!change) return;
    if (steps.change_step == 0) {
        const std::int64_t now = wall.now_ns();
        const std::int64_t at =
            change_time(*change, now, change_boundary(now, params.get<ParamId::wall_change_period>()));
        const double rate = params.get<ParamId::wave_steps_per_second>();
        steps.change_step = static_cast<std::uint64_t>(std::max<std::int64_t>(1, step_at(at, rate)));
        spdlog::info("{}: applies at {} (step {}), with the wall", change->reason, utc_text(at, now),
                     steps.change_step);
    }
    const bool due = power.on ? clock.step_index + 1 >= steps.change_step
                              : step_at(wall.now_ns(), params.get<ParamId::wave_steps_per_second>()) >=
                                    static_cast<std::int64_t>(steps.change_step);
    if (!due) return;
    steps.change_step = 0;
    apply_pending_change(tuning, params);
}

}  // namespace puddle::systems
