#include "params/param_layers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "params/wall_check.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

ParamValue clamp_to_range(const ParamDecl& d, ParamValue v) {
    if (auto* i = std::get_if<int>(&v)) *i = std::clamp(*i, static_cast<int>(d.min), static_cast<int>(d.max));
    if (auto* f = std::get_if<float>(&v))
        *f = std::clamp(*f, static_cast<float>(d.min), static_cast<float>(d.max));
    return v;
}

ParamLayers::ParamLayers(Presets presets, std::vector<ConfigEntry> command_line)
    : presets_(std::move(presets)), command_line_(std::move(command_line)) {}

Result<void> ParamLayers::resolve_preset(const std::string& name, Config& out) const {
    if (name.empty()) {
        out = Config{};
        return {};
    }
    auto preset = presets_.get(name);
    if (!preset) return preset.error();
    out = std::move(*preset);
    return {};
}

Result<void> ParamLayers::set_command_line_preset(const std::string& name) {
    Config preset;
    if (auto r = resolve_preset(name, preset); !r) {
        std::string_view inner = r.error().message;
        if (inner.starts_with("config: ")) inner.remove_prefix(8);
        return make_error(ExitCode::Config, "--preset {}: {}", safe_quote(name), inner);
    }
    command_line_preset_ = name;
    if (knob_preset_.empty()) {
        preset_ = std::move(preset);
        preset_name_ = name;
    }
    return {};
}

Result<void> ParamLayers::set_config(Config config) {
    const std::string configured =
        command_line_preset_.empty() ? config.preset.value_or("") : command_line_preset_;
    const std::string name = knob_preset_.empty() ? configured : knob_preset_;
    Config preset;
    if (auto r = resolve_preset(name, preset); !r) {
        if (!knob_preset_.empty() || !command_line_preset_.empty()) return r;
        // "config: PRESET:2: ..." (a broken preset file) already names its file; say which line chose it.
        std::string_view inner = r.error().message;
        if (inner.starts_with("config: ")) inner.remove_prefix(8);
        return make_error(ExitCode::Config, "config: {}:{}: preset = \"{}\": {}", config.path,
                          config.preset_line, name, inner);
    }
    std::vector<Config> schedule_presets(config.schedule.size());
    for (std::size_t i = 0; i < config.schedule.size(); ++i) {
        const ScheduleEntry& e = config.schedule[i];
        if (!e.preset) continue;
        if (auto r = resolve_preset(*e.preset, schedule_presets[i]); !r) {
            std::string_view inner = r.error().message;
            if (inner.starts_with("config: ")) inner.remove_prefix(8);
            return make_error(ExitCode::Config, "config: {}:{}: schedule[{}]: preset = \"{}\": {}",
                              config.path, e.line, e.number, *e.preset, inner);
        }
    }
    // The rules across keys, on the preset, the config and the command line together.
    Params trial;
    apply_config(preset, trial, ParamSource::Preset);
    apply_config(config, trial, ParamSource::Config);
    for (const ConfigEntry& e : command_line_) trial.set(e.id, e.value, ParamSource::CommandLine);
    if (auto r = check_wall(trial, config); !r) return r;
    config_ = std::move(config);
    preset_ = std::move(preset);
    preset_name_ = name;
    schedule_presets_ = std::move(schedule_presets);
    std::erase_if(schedule_active_, [&](int i) { return i >= static_cast<int>(config_.schedule.size()); });
    return {};
}

Result<void> ParamLayers::set_presets_and_config(Presets presets, Config config) {
    Presets kept = std::exchange(presets_, std::move(presets));
    if (auto r = set_config(std::move(config)); !r) {
        presets_ = std::move(kept);
        return r;
    }
    return {};
}

Result<void> ParamLayers::select_preset(const std::string& name) {
    const std::string configured =
        command_line_preset_.empty() ? config_.preset.value_or("") : command_line_preset_;
    const std::string effective = name.empty() ? configured : name;
    Config preset;
    if (auto r = resolve_preset(effective, preset); !r) return r;
    knob_preset_ = name;
    preset_ = std::move(preset);
    preset_name_ = effective;
    return {};
}

void ParamLayers::set_knob(ParamId id, ParamValue value) {
    knob_[static_cast<std::size_t>(id)] = clamp_to_range(decl(id), std::move(value));
    remote_[static_cast<std::size_t>(id)] = false;
}

void ParamLayers::clear_knob(ParamId id) {
    knob_[static_cast<std::size_t>(id)].reset();
    remote_[static_cast<std::size_t>(id)] = false;
}

void ParamLayers::set_remote(ParamId id, ParamValue value) {
    set_knob(id, std::move(value));
    remote_[static_cast<std::size_t>(id)] = true;
}

Result<void> ParamLayers::restore_state(const Config& state) {
    for (const ConfigEntry& e : state.entries) set_knob(e.id, e.value);
    for (const ParamId id : state.remote)
        if (knob_[static_cast<std::size_t>(id)]) remote_[static_cast<std::size_t>(id)] = true;
    if (state.preset && *state.preset != knob_preset_) {
        if (auto r = select_preset(*state.preset); !r)
            return make_error(ExitCode::Config, "state: {}: saved preset '{}' is gone; using the config's",
                              state.path, safe_quote(*state.preset));
    }
    return {};
}

std::string ParamLayers::state_text() const {
    std::string out = "# Written by puddle: what the knobs changed. Delete this file to forget it.\n";
    if (!knob_preset_.empty()) out += fmt::format("preset = \"{}\"\n", knob_preset_);
    std::string remote;  // which values came from the broker (Config::remote)
    for (const ParamDecl& d : param_decls())
        if (remote_[static_cast<std::size_t>(d.id)] && knob_[static_cast<std::size_t>(d.id)])
            remote += fmt::format("{}\"{}\"", remote.empty() ? "" : ", ", d.name);
    if (!remote.empty()) out += fmt::format("remote = [{}]\n", remote);
    std::string_view section;
    for (const ParamDecl& d : param_decls()) {
        const auto& v = knob_[static_cast<std::size_t>(d.id)];
        if (!v) continue;
        const std::size_t dot = d.name.find('.');
        if (d.name.substr(0, dot) != section) {
            section = d.name.substr(0, dot);
            out += fmt::format("[{}]\n", section);
        }
        out += fmt::format("{} = {}\n", d.name.substr(dot + 1), format_value(*v));
    }
    return out;
}

bool ParamLayers::set_active_schedule(std::vector<int> active) {
    std::erase_if(active, [&](int i) { return i < 0 || i >= static_cast<int>(config_.schedule.size()); });
    if (active == schedule_active_) return false;
    schedule_active_ = std::move(active);
    return true;
}

bool ParamLayers::clear_knobs_set_by(int entry) {
    if (entry < 0 || entry >= static_cast<int>(config_.schedule.size())) return false;
    bool held = false;
    auto clear = [&](ParamId id) {
        held |= std::exchange(knob_[static_cast<std::size_t>(id)], std::nullopt).has_value();
        remote_[static_cast<std::size_t>(id)] = false;  // a remote value is forgotten the same way
    };
    for (const ConfigEntry& e : schedule_presets_[static_cast<std::size_t>(entry)].entries) clear(e.id);
    for (const ScheduledValue& v : config_.schedule[static_cast<std::size_t>(entry)].values) clear(v.id);
    return held;
}

std::array<int, param_count> ParamLayers::schedule_entries() const {
    std::array<int, param_count> out{};
    for (int i : schedule_active_) {
        const auto k = static_cast<std::size_t>(i);
        for (const ConfigEntry& e : schedule_presets_[k].entries)
            out[static_cast<std::size_t>(e.id)] = config_.schedule[k].number;
        for (const ScheduledValue& v : config_.schedule[k].values)
            out[static_cast<std::size_t>(v.id)] = config_.schedule[k].number;
    }
    return out;
}

std::vector<std::string> ParamLayers::active_schedule_presets() const {
    std::vector<std::string> out;
    for (int i : schedule_active_) {
        const ScheduleEntry& e = config_.schedule[static_cast<std::size_t>(i)];
        if (e.preset) out.push_back(fmt::format("schedule[{}] {}", e.number, *e.preset));
    }
    return out;
}

Params ParamLayers::compose() const {
    Params p;
    apply_config(preset_, p, ParamSource::Preset);
    apply_config(config_, p, ParamSource::Config);
    for (int i : schedule_active_) {
        const auto k = static_cast<std::size_t>(i);
        apply_config(schedule_presets_[k], p, ParamSource::Schedule);
        for (const ScheduledValue& v : config_.schedule[k].values)
            p.set(v.id, v.value, ParamSource::Schedule);
    }
    for (const ParamDecl& d : param_decls())
        if (const auto& v = knob_[static_cast<std::size_t>(d.id)])
            p.set(d.id, *v,
                  remote_[static_cast<std::size_t>(d.id)] ? ParamSource::Remote : ParamSource::Knob);
    for (const ConfigEntry& e : command_line_) p.set(e.id, e.value, ParamSource::CommandLine);
    return p;
}

}  // namespace puddle::params
