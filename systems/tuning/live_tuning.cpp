#include "systems/tuning/live_tuning.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace puddle::systems {

using params::ParamId;
using params::ParamKind;

namespace {

// A refusal or a full disk fails every save alike: one line, not one per knob turn. What a failed save
// did not write is still to be saved: it is tried again a delay later, and at exit.
void report_save(LiveTuning& t, const Result<void>& saved, double now) {
    if (!saved) {
        if (saved.error().message != t.last_save_problem) spdlog::warn("{}", saved.error().message);
        t.last_save_problem = saved.error().message;
        t.state_dirty = true;
        t.last_knob_change = std::max(t.last_knob_change, now);
    } else {
        t.last_save_problem.clear();
        spdlog::info("state: knob values saved to {}", t.state->path());
    }
}

void make_knobs(LiveTuning& t) {
    t.knobs.clear();
    const auto& specs = t.layers.config().knobs;
    if (specs.empty()) return;
    if (!t.gpio) t.gpio = io::make_gpiod_backend();
    t.knobs.reserve(specs.size());
    for (const auto& spec : specs) t.knobs.emplace_back(spec);
    t.actions.reserve(64 * specs.size());
    spdlog::info("gpio: {} knob(s) on {}", specs.size(), t.gpio->name());
}

// One line listing what a recompose changed, e.g. "rain.intensity 0.3 -> 0.5 (knob)".
std::string describe_changes(const params::Params& before, const params::Params& after) {
    std::string out;
    int n = 0;
    for (const auto& d : params::param_decls()) {
        if (before.at(d.id) == after.at(d.id)) continue;
        if (n++ < 6)
            out += fmt::format("{}{} {} -> {} ({})", out.empty() ? "" : ", ", d.name,
                               params::format_value(before.at(d.id)), params::format_value(after.at(d.id)),
                               params::source_name(after.source(d.id)));
    }
    if (n > 6) out += fmt::format(" and {} more", n - 6);
    return n ? out : "no value changed";
}

void apply_action(LiveTuning& t, const io::KnobAction& a, const params::Params& current, double now) {
    const params::KnobSpec& k = *a.knob;
    switch (a.kind) {
        case io::KnobAction::Kind::Turn: {
            const auto& d = params::decl(*k.param);
            const auto& held = t.layers.knob(*k.param);
            const bool was_held = held.has_value();
            const params::ParamValue base =
                held ? *held : current.at(*k.param);  // a copy: set_knob changes held
            if (d.kind == ParamKind::Int) {
                const double step = a.amount >= 0 ? std::max(1.0, std::round(a.amount))
                                                  : std::min(-1.0, std::round(a.amount));
                t.layers.set_knob(*k.param,
                                  static_cast<int>(std::clamp(std::get<int>(base) + step, d.min, d.max)));
            } else {
                // Snapped to a thousandth of the knob's step: float sums drift (0.5 + 8 x 0.1 = 1.3000001),
                // and the value is shown, logged and saved as it is.
                const double step = k.step != 0 ? k.step : (d.max - d.min) / 50.0;  // as the knob's default
                const double grid = std::abs(step) / 1000.0;
                double v = static_cast<double>(std::get<float>(base)) + a.amount;
                if (grid > 0) v = std::round(v / grid) * grid;
                t.layers.set_knob(*k.param, static_cast<float>(v));
            }
            if (was_held && *t.layers.knob(*k.param) == base) {  // turned on past an end of its range
                spdlog::debug("knob: {} stays at {} (allowed {})", d.name, params::format_value(base),
                              params::describe_range(d));
                return;
            }
            break;
        }
        case io::KnobAction::Kind::Level:
            t.layers.set_knob(*k.param, a.level);
            break;
        case io::KnobAction::Kind::Press:
            switch (k.action) {
                case params::ButtonAction::NextPreset:
                case params::ButtonAction::PreviousPreset: {
                    const int dir = k.action == params::ButtonAction::NextPreset ? 1 : -1;
                    const std::string next = t.layers.presets().step(t.layers.preset_name(), dir);
                    if (auto r = t.layers.select_preset(next); !r)
                        spdlog::warn("{}", r.error().message);
                    else
                        spdlog::info("preset: {} (knob)", next);
                    break;
                }
                case params::ButtonAction::Reset:
                    t.layers.clear_knob(*k.param);
                    break;
                case params::ButtonAction::Toggle: {
                    const auto& held = t.layers.knob(*k.param);
                    t.layers.set_knob(*k.param, !std::get<bool>(held ? *held : current.at(*k.param)));
                    break;
                }
                case params::ButtonAction::SaveState:
                    t.state_dirty = true;
                    start_state_save(t);
                    return;
            }
            break;
    }
    t.layers_changed = true;
    t.change_reason = "knob";
    t.state_dirty = true;
    t.last_knob_change = now;
}

}  // namespace

void start_live_tuning(LiveTuning& t) {
    make_knobs(t);
    if (t.config_path.empty()) return;
    auto watcher = params::ConfigWatcher::watch(t.config_path);
    if (!watcher) {
        spdlog::warn("{}; edits apply on SIGHUP only", watcher.error().message);
        return;
    }
    t.watcher = std::move(*watcher);
    spdlog::info("config: watching {} for changes (or send SIGHUP)", t.config_path);
}

bool reload_config(LiveTuning& t) {
    if (t.config_path.empty()) return false;
    auto config = params::load_config_file(t.config_path);
    if (!config) {
        spdlog::error("{} (keeping the last good configuration)", config.error().message);
        return false;
    }
    const bool knobs_changed = config->knobs != t.layers.config().knobs;
    if (auto r = t.layers.set_presets_and_config(params::Presets::load(t.preset_folders), std::move(*config));
        !r) {
        spdlog::error("{} (keeping the last good configuration)", r.error().message);
        return false;
    }
    if (knobs_changed) make_knobs(t);
    ++t.config_generation;
    t.layers_changed = true;
    t.change_reason = "config: reloaded";
    return true;
}

void live_tuning_step(LiveTuning& t, params::Params& params, double now) {
    t.last_step = now;
    bool reload = std::exchange(t.reload_requested, false);
    if (t.watcher) {
        switch (t.watcher->poll()) {
            case params::ConfigWatcher::Change::Written:
                reload = true;
                break;
            case params::ConfigWatcher::Change::Removed:
                spdlog::warn("config: {} was removed; keeping the last good configuration until it is back",
                             t.config_path);
                break;
            case params::ConfigWatcher::Change::None:
                break;
        }
    }
    if (reload) reload_config(t);

    if (t.gpio && !t.knobs.empty()) {
        t.gpio->poll(now);
        t.actions.clear();
        for (io::Knob& k : t.knobs) k.update(*t.gpio, now, t.actions, t.gone_chips);
        for (const io::KnobAction& a : t.actions) apply_action(t, a, params, now);
        t.actions.clear();
    }
    if (auto saved = t.saver ? t.saver->take() : std::nullopt) report_save(t, *saved, now);
    if (t.state_dirty && t.state && now - t.last_knob_change >= LiveTuning::save_delay_seconds)
        start_state_save(t);

    if (!t.layers_changed) return;
    if (params.get<ParamId::wall_clock>() == params::WallClockMode::realtime) return;  // synced_changes.hpp
    t.layers_changed = false;
    apply_layers(t, params, t.change_reason);
}

void apply_layers(LiveTuning& t, params::Params& params, std::string_view reason) {
    const params::Params next = t.layers.compose();
    const std::string changes = describe_changes(params, next);
    params.replace_with(next);
    spdlog::info("{}: {}", reason, changes);
}

void start_state_save(LiveTuning& t) {
    if (!t.state_dirty || !t.state || !t.saver) return;
    t.state_dirty = false;
    // Only the saver thread touches the store from here on; a newer save replaces one still waiting.
    t.saver->submit(
        [store = &*t.state, text = t.layers.state_text()](std::stop_token) { return store->save(text); });
}

void finish_state_save(LiveTuning& t) {
    if (!t.saver) return;
    while (t.saver->running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (auto saved = t.saver->take()) report_save(t, *saved, t.last_step);
}

void save_state(LiveTuning& t) {
    if (!t.state) return;
    finish_state_save(t);  // a save submitted earlier wrote what was current then
    t.saver.reset();       // no thread touches the store any more
    if (!t.state_dirty) return;
    t.state_dirty = false;
    report_save(t, t.state->save(t.layers.state_text()), t.last_step);
}

void live_tuning_system(LiveTuning& tuning, params::Params& params) {
    live_tuning_step(tuning, params, monotonic_seconds());
}

Result<void> add_live_tuning(ecs::World& world, ecs::Schedule& schedule, LiveTuning tuning) {
    start_live_tuning(world.insert_resource<LiveTuning>(std::move(tuning)));
    schedule.add(ecs::Stage::Input, "live tuning", live_tuning_system);
    schedule.add(ecs::Stage::Exit, "save state", save_state);
    return {};
}

}  // namespace puddle::systems
