#pragma once
// Where values come from while the program runs, lowest to highest precedence:
//   built-in defaults < preset < config file < schedule < knob and remote state < --set
// A remote (MQTT) value shares the knob level: whichever set the parameter last holds it, and both are
// saved in the same state file.
// Each source is kept as its own layer; any change recomposes the effective Params from all of them, so
// a reloaded config never overwrites a knob's value and a removed config line falls back to the preset
// or the default.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "params/config_loader.hpp"
#include "params/param_store.hpp"
#include "params/presets.hpp"

namespace puddle::params {

class ParamLayers {
public:
    ParamLayers(Presets presets, std::vector<ConfigEntry> command_line);

    // Makes `config` the config layer, with the preset it names. Validates everything first, the rules
    // across keys too (params/wall_check.hpp): on error nothing changes (the last good config keeps running).
    Result<void> set_config(Config config);
    // The same with the presets read again (their files may have been edited): both or neither change.
    Result<void> set_presets_and_config(Presets presets, Config config);
    const Config& config() const { return config_; }

    // `--preset NAME`: used instead of the config's `preset =` (now and at every reload); a knob's choice
    // still wins over it, as over the config's. Errors: "--preset NAME: ..." when there is no such preset.
    Result<void> set_command_line_preset(const std::string& name);
    // A preset chosen with a knob's button; it wins over the config's `preset =`. Empty: the config's.
    Result<void> select_preset(const std::string& name);
    // The preset in effect ("" for none).
    const std::string& preset_name() const { return preset_name_; }
    const Presets& presets() const { return presets_; }

    // Knob state. The value is clamped to the parameter's registered range.
    void set_knob(ParamId id, ParamValue value);
    void clear_knob(ParamId id);
    // A value from the broker (validated by the caller, as the config's are): the knob level, source Remote.
    void set_remote(ParamId id, ParamValue value);
    bool is_remote(ParamId id) const { return remote_[static_cast<std::size_t>(id)]; }
    const std::optional<ParamValue>& knob(ParamId id) const { return knob_[static_cast<std::size_t>(id)]; }
    // Restores saved knob state (a state file: `preset =` and parameter values); unknown presets are
    // dropped with the returned warning.
    Result<void> restore_state(const Config& state);
    // The knob state as the text of a state file.
    std::string state_text() const;

    // The schedule layer, between the config and the knobs: the config's [[schedule]] entries active now,
    // as indices into config().schedule in file order; each applies its preset's values, then its own, and
    // a later entry wins. set_config keeps only indices that still exist: the schedule system evaluates
    // the new entries (systems/tuning/schedule_system.hpp). Returns true when the set changed.
    bool set_active_schedule(std::vector<int> active);
    const std::vector<int>& active_schedule() const { return schedule_active_; }
    // At a schedule transition: forgets the knob values of the parameters entry `entry` sets (its values
    // and its preset's), so the schedule applies again. True when a knob value was held.
    bool clear_knobs_set_by(int entry);
    // Per parameter, the number N of the active entry (schedule[N]) whose value the schedule layer gives,
    // 0 where it gives none (--print-config).
    std::array<int, param_count> schedule_entries() const;
    // The presets the active entries apply, as "schedule[N] name", in file order (--print-config's header).
    std::vector<std::string> active_schedule_presets() const;

    Params compose() const;

private:
    Result<void> resolve_preset(const std::string& name, Config& out) const;
    Presets presets_;
    Config config_;
    std::string preset_name_;
    Config preset_;
    std::string knob_preset_;
    std::string command_line_preset_;  // --preset; empty: the config's
    std::array<std::optional<ParamValue>, param_count> knob_{};
    std::array<bool, param_count> remote_{};  // knob_[id] came from the broker
    std::vector<ConfigEntry> command_line_;
    std::vector<Config> schedule_presets_;  // each entry's preset (empty without one), as config_.schedule
    std::vector<int> schedule_active_;
};

// Clamps a number to its declaration's range (other kinds unchanged).
ParamValue clamp_to_range(const ParamDecl& d, ParamValue v);

}  // namespace puddle::params
