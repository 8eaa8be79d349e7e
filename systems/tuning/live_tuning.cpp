#include "systems/tuning/live_tuning.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <utility>
#include <variant>

namespace puddle::systems {

using params::ParamId;
using params::ParamKind;

// The one way into LiveTuning's internals: this file's functions are live tuning.
struct LiveTuningAccess {
    static LiveTuning::Internals& of(LiveTuning& t) { return t.in_; }
    static const LiveTuning::Internals& of(const LiveTuning& t) { return t.in_; }
};

namespace {

auto& in(LiveTuning& t) {
    return LiveTuningAccess::of(t);
}
const auto& in(const LiveTuning& t) {
    return LiveTuningAccess::of(t);
}

// A change of a layer from `reason`, applied by this step (or, on a wall, at the wall's step), and saved
// a delay later.
void layer_changed(LiveTuning& t, const char* reason, double now) {
    in(t).layers_changed = true;
    in(t).change_reason = reason;
    in(t).state_dirty = true;
    in(t).last_knob_change = now;
}

// Acts on one request from the inbox; true when it asks for a config reload.
bool act_on(LiveTuning& t, const TuningRequest& request, double now) {
    if (const auto* set = std::get_if<SetRemoteValue>(&request)) {
        t.layers.set_remote(set->id, set->value);
        if (set->apply_at_ns) in(t).apply_at_ns = set->apply_at_ns;  // wall.clock = "realtime" only reads it
        layer_changed(t, "remote", now);
        return false;
    }
    if (const auto* preset = std::get_if<SelectPreset>(&request)) {
        if (auto r = t.layers.select_preset(preset->name); !r) {
            spdlog::warn("{} (preset not changed)", r.error().message);
            return false;
        }
        spdlog::info("preset: {} ({})", preset->name.empty() ? "the config's" : preset->name, preset->source);
        if (preset->apply_at_ns) in(t).apply_at_ns = preset->apply_at_ns;
        layer_changed(t, preset->source, now);
        return false;
    }
    if (const auto* entries = std::get_if<SetSchedule>(&request)) {
        bool forgot = false;
        for (int entry : entries->forget_knobs_of) forgot |= forget_knobs_set_by(t, entry);
        if (t.layers.set_active_schedule(entries->active) || forgot) {
            in(t).schedule_reason = entries->reason;
            in(t).layers_changed = true;
            in(t).change_reason = in(t).schedule_reason.c_str();
        }
        return false;
    }
    if (std::holds_alternative<SaveState>(request)) {
        in(t).state_dirty = true;
        start_state_save(t);
        return false;
    }
    return std::holds_alternative<ReloadConfig>(request);
}

// A refusal or a full disk fails every save alike: one line, not one per knob turn. What a failed save
// did not write is still to be saved: it is tried again a delay later, and at exit.
void report_save(LiveTuning& t, const Result<void>& saved, double now) {
    if (!saved) {
        if (saved.error().message != in(t).last_save_problem) spdlog::warn("{}", saved.error().message);
        in(t).last_save_problem = saved.error().message;
        in(t).state_dirty = true;
        in(t).last_knob_change = std::max(in(t).last_knob_change, now);
    } else {
        in(t).last_save_problem.clear();
        spdlog::info("state: knob values saved to {}", t.state->path());
    }
}

void make_knobs(LiveTuning& t) {
    in(t).knobs.clear();
    const auto& specs = t.layers.config().knobs;
    if (specs.empty()) return;
    if (!t.gpio) t.gpio = io::make_gpiod_backend();
    in(t).knobs.reserve(specs.size());
    for (const auto& spec : specs) in(t).knobs.emplace_back(spec);
    in(t).actions.reserve(64 * specs.size());
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
                    in(t).state_dirty = true;
                    start_state_save(t);
                    return;
            }
            break;
    }
    in(t).layers_changed = true;
    in(t).change_reason = "knob";
    in(t).state_dirty = true;
    in(t).last_knob_change = now;
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
    in(t).watcher = std::move(*watcher);
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
    ++in(t).config_generation;
    in(t).layers_changed = true;
    in(t).change_reason = "config: reloaded";
    return true;
}

void live_tuning_step(TuningInbox& inbox, LiveTuning& t, params::Params& params, double now) {
    in(t).last_step = now;
    bool reload = false;
    for (const TuningRequest& request : inbox.requests) reload |= act_on(t, request, now);
    inbox.requests.clear();
    if (const std::uint64_t dropped = std::exchange(inbox.dropped, 0))
        spdlog::warn("tuning: {} change(s) dropped: more than {} asked in one frame", dropped,
                     TuningInbox::capacity);
    if (in(t).watcher) {
        switch (in(t).watcher->poll()) {
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

    if (t.gpio && !in(t).knobs.empty()) {
        t.gpio->poll(now);
        in(t).actions.clear();
        for (io::Knob& k : in(t).knobs) k.update(*t.gpio, now, in(t).actions, in(t).gone_chips);
        for (const io::KnobAction& a : in(t).actions) apply_action(t, a, params, now);
        in(t).actions.clear();
    }
    if (auto saved = in(t).saver ? in(t).saver->take() : std::nullopt) report_save(t, *saved, now);
    if (in(t).state_dirty && t.state && now - in(t).last_knob_change >= LiveTuning::save_delay_seconds)
        start_state_save(t);

    if (!in(t).layers_changed) return;
    if (params.get<ParamId::wall_clock>() == params::WallClockMode::realtime) return;  // synced_changes.hpp
    in(t).layers_changed = false;
    apply_layers(t, params, in(t).change_reason);
}

void apply_layers(LiveTuning& t, params::Params& params, std::string_view reason) {
    const params::Params next = t.layers.compose();
    const std::string changes = describe_changes(params, next);
    params.replace_with(next);
    spdlog::info("{}: {}", reason, changes);
}

void start_state_save(LiveTuning& t) {
    if (!in(t).state_dirty || !t.state || !in(t).saver) return;
    in(t).state_dirty = false;
    // Only the saver thread touches the store from here on; a newer save replaces one still waiting.
    in(t).saver->submit(
        [store = &*t.state, text = t.layers.state_text()](std::stop_token) { return store->save(text); });
}

void finish_state_save(LiveTuning& t) {
    if (!in(t).saver) return;
    while (in(t).saver->running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (auto saved = in(t).saver->take()) report_save(t, *saved, in(t).last_step);
}

void save_state(LiveTuning& t) {
    if (!t.state) return;
    finish_state_save(t);  // a save submitted earlier wrote what was current then
    in(t).saver.reset();   // no thread touches the store any more
    if (!in(t).state_dirty) return;
    in(t).state_dirty = false;
    report_save(t, t.state->save(t.layers.state_text()), in(t).last_step);
}

std::optional<PendingChange> pending_change(const LiveTuning& t) {
    if (!in(t).layers_changed) return std::nullopt;
    return PendingChange{in(t).change_reason, in(t).apply_at_ns};
}

void apply_pending_change(LiveTuning& t, params::Params& params) {
    in(t).layers_changed = false;
    in(t).apply_at_ns.reset();
    apply_layers(t, params, in(t).change_reason);
}

bool forget_knobs_set_by(LiveTuning& t, int entry) {
    if (!t.layers.clear_knobs_set_by(entry)) return false;
    in(t).state_dirty = true;  // the knob values it forgot are forgotten on disk too
    return true;
}

void live_tuning_system(TuningInbox& inbox, LiveTuning& tuning, params::Params& params) {
    live_tuning_step(inbox, tuning, params, monotonic_seconds());
}

Result<void> add_live_tuning(ecs::World& world, ecs::Schedule& schedule, LiveTuning tuning) {
    if (!world.try_resource<TuningInbox>()) world.insert_resource<TuningInbox>();
    start_live_tuning(world.insert_resource<LiveTuning>(std::move(tuning)));
    schedule.add(ecs::Stage::Input, "live tuning", live_tuning_system);
    schedule.add(ecs::Stage::Exit, "save state", save_state);
    return {};
}

}  // namespace puddle::systems
