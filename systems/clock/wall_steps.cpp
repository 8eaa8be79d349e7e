#include "systems/clock/wall_steps.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace puddle::systems {

using params::ParamId;

namespace {

// Starts the field flat `warmup` steps before `target`: the next frames simulate up to it.
void restart(FrameClock& clock, WallSteps& steps, std::int64_t target, std::int64_t warmup,
             std::int64_t now_ns) {
    clock.step_index = static_cast<std::uint64_t>(target - warmup);
    ++clock.field_generation;
    ++steps.resyncs;
    steps.restart_ns = now_ns;
    steps.restart_step = clock.step_index;
    steps.reached_clock = warmup == 0;
}

// The screen fell further behind than the warm-up before its last warm-up ever reached the clock: say
// so (once a run) with the pace it reached, and follow the clock's time from now on.
void fall_behind_the_wall(WallSteps& steps, const FrameClock& clock, const params::Params& params,
                          std::int64_t now_ns, double rate) {
    const double seconds = static_cast<double>(now_ns - steps.restart_ns) * 1e-9;
    const double pace =
        seconds > 0 ? static_cast<double>(clock.step_index - steps.restart_step) / seconds : 0.0;
    steps.behind_the_wall = true;
    steps.behind_resolution = params.get<ParamId::wave_resolution>();
    steps.behind_rate = rate;
    const auto level = steps.behind_said ? spdlog::level::debug : spdlog::level::warn;
    steps.behind_said = true;
    spdlog::log(level,
                "wall: this screen cannot keep the wall's pace: it simulated {:.0f} wave steps a second, the "
                "wall runs {:.0f} (wave.steps_per_second); its ripples will not match the other screens'. "
                "It now follows the wall's time at {} steps a frame at most. Lower wave.resolution (now {}) "
                "on every screen of the wall",
                pace, rate, behind_steps_per_frame, steps.behind_resolution);
}

// Why a re-sync is due, or null: the caller logs it with the clock's gap.
const char* resync_reason(const WallSteps& steps, bool field_needed, std::int64_t behind, std::int64_t warmup,
                          std::int64_t max_hold) {
    if (!steps.joined) return "joining the wall clock";
    if (field_needed && !steps.field_in_use) return "the wave field is in use again";
    if (behind > warmup) return "the clock is ahead of the picture";
    if (behind < -max_hold) return "the clock went back";
    return nullptr;
}

}  // namespace

void wall_steps_system(const WallClock& wall, const OutputPower& power, const ShownLook& look,
                       const params::Params& params, WallSteps& steps, FrameClock& clock) {
    clock.steps_due = 0;
    if (!power.on) return;  // nothing is simulated while off; waking is a forward step (see the header)
    if (!steps.sync_checked) {
        steps.sync_checked = true;
        if (const ClockSync sync = wall.sync(); !sync.synchronised)
            spdlog::warn(
                "wall: the system clock is {}: screens of a wall will drift apart (docs/video-walls.md)",
                describe(sync));
    }
    const double rate = params.get<ParamId::wave_steps_per_second>();
    const double step_seconds = 1.0 / rate;
    if (steps.joined && step_seconds != clock.step_seconds) {
        // The same step index on every screen maps to the same new one, so a synced change of the rate
        // keeps the wall in step without a re-sync.
        clock.step_index = static_cast<std::uint64_t>(
            std::floor(static_cast<double>(clock.step_index) * clock.step_seconds * rate));
    }
    // Step n is at n / rate seconds since the Unix epoch: sim_time is a function of the step alone.
    clock.step_seconds = step_seconds;
    clock.epoch_time = 0.0;
    clock.epoch_step = 0;
    clock.accumulator = 0.0;

    const auto latency = std::llround(static_cast<double>(params.get<ParamId::wall_latency>()) * 1e9);
    const std::int64_t now = wall.now_ns();  // one reading a frame: the target, the pace and a restart agree
    const std::int64_t target = step_at(now + latency, rate);
    steps.target_step = target;
    const bool field_needed = look.scene == Scene::puddle && look.drops == DropModel::pulse;
    // Looks without the wave field are functions of the step alone: they jump straight to it.
    const std::int64_t warmup =
        field_needed ? std::llround(static_cast<double>(params.get<ParamId::wall_warmup>()) * rate) : 0;
    const std::int64_t max_hold = std::llround(max_hold_seconds * rate);
    std::int64_t behind = target - static_cast<std::int64_t>(clock.step_index);
    if (steps.behind_the_wall &&
        (params.get<ParamId::wave_resolution>() != steps.behind_resolution || rate != steps.behind_rate)) {
        steps.behind_the_wall = false;  // a cheaper field may keep the pace: try the wall's steps again
        spdlog::info("wall: the wave field's cost changed: trying the wall's pace again");
        steps.joined = false;
    }
    // Behind the wall: skip ahead to the clock's step (never past a pending change's or the screenshot's),
    // leaving a few steps for this frame.
    const auto follow_the_clocks_time = [&] {
        std::int64_t to = target;
        if (steps.stop_step != 0) to = std::min(to, steps.stop_step);
        if (steps.change_step != 0) to = std::min(to, static_cast<std::int64_t>(steps.change_step) - 1);
        const auto from = static_cast<std::int64_t>(clock.step_index);
        clock.step_index = static_cast<std::uint64_t>(std::max(from, to - behind_steps_per_frame));
        behind = std::clamp<std::int64_t>(target - static_cast<std::int64_t>(clock.step_index), 0,
                                          behind_steps_per_frame);
    };
    if (steps.behind_the_wall && field_needed && steps.field_in_use && behind > -max_hold) {
        follow_the_clocks_time();
    } else if (const char* why = resync_reason(steps, field_needed, behind, warmup, max_hold)) {
        if (steps.joined && field_needed && steps.field_in_use && behind > warmup && !steps.reached_clock) {
            fall_behind_the_wall(steps, clock, params, now, rate);
            follow_the_clocks_time();
        } else {
            if (steps.joined)
                spdlog::info("wall: {} ({:+.3f} s): re-syncing, {} steps of warm-up", why,
                             static_cast<double>(behind) * step_seconds, warmup);
            else
                spdlog::info("wall: {} at step {} ({} steps/s), {} steps of warm-up", why, target, rate,
                             warmup);
            restart(clock, steps, target, warmup, now);
            behind = warmup;
        }
    }
    steps.joined = true;
    steps.field_in_use = field_needed;
    std::int64_t due = std::clamp<std::int64_t>(behind, 0, params.get<ParamId::wall_catch_up_steps>());
    if (due >= behind) steps.reached_clock = true;
    if (steps.change_step != 0)  // the change's step waits for the change (systems/tuning/synced_changes.hpp)
        due = std::clamp<std::int64_t>(
            static_cast<std::int64_t>(steps.change_step) - 1 - static_cast<std::int64_t>(clock.step_index), 0,
            due);
    if (steps.stop_step != 0)
        due = std::clamp<std::int64_t>(steps.stop_step - static_cast<std::int64_t>(clock.step_index), 0, due);
    clock.steps_due = static_cast<int>(due);
}

std::optional<std::string> wall_timing_problem(const params::Params& params) {
    const bool realtime = params.get<ParamId::wall_clock>() == params::WallClockMode::realtime;
    const int screens = params.get<ParamId::wall_columns>() * params.get<ParamId::wall_rows>();
    if (screens > 1 && !realtime)
        return fmt::format(
            "a wall of {} screens with wall.clock = \"frame\": each screen counts time from its own start, "
            "so "
            "the ripples will not run on from one screen to the next; set [wall] clock = \"realtime\" on "
            "every screen (docs/video-walls.md, \"One clock for every screen\")",
            screens);
    // Each wave model forgets how it started only through its own damping: wave.damping for the
    // reference's equation, wave.drag (every wavelength alike) for the capillary one, whose viscosity
    // hardly touches the long waves.
    const bool capillary = params.get<ParamId::wave_model>() == params::WaveModel::capillary;
    if (realtime && !capillary && params.get<ParamId::wave_damping>() >= 1.0f)
        return std::string(
            "wall.clock = \"realtime\" with wave.damping = 1: an undamped field never forgets how it "
            "started, so screens that joined at different times never match; use a wave.damping below 1 "
            "(0.985 is the default)");
    if (realtime && capillary && params.get<ParamId::wave_drag>() <= 0.0f)
        return std::string(
            "wall.clock = \"realtime\" with wave.drag = 0: the capillary field's long waves never fade, so "
            "screens that joined at different times never match; use a wave.drag above 0 (1.5 /s is the "
            "default)");
    return std::nullopt;
}

ecs::RunCondition wall_clock_is(params::WallClockMode mode) {
    return {"wall.clock is " + std::string(params::choice_name(mode)), [mode](ecs::World& w) {
                return w.resource<params::Params>().get<ParamId::wall_clock>() == mode;
            }};
}

}  // namespace puddle::systems
