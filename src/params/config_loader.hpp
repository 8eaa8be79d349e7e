#pragma once
// The TOML config: `[section]` tables whose keys are the registry's names (`[rain] drop_count = 20`
// is rain.drop_count), an optional top-level `preset = "name"`, `[[knob]]` tables, `[[schedule]]`
// tables and `[location]` (params/schedule_spec.hpp). Presets and the
// saved state use the same format. A file is validated completely before anything is applied; the
// first problem is reported with file:line, the key, the value and what is allowed.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "params/knob_spec.hpp"
#include "params/param_store.hpp"
#include "params/schedule_spec.hpp"
#include "util/result.hpp"

namespace puddle::params {

struct ConfigEntry {
    ParamId id;
    ParamValue value;
    int line = 0;
};

struct Config {
    std::string path;
    std::vector<ConfigEntry> entries;
    std::optional<std::string> preset;  // top-level `preset = "downpour"`
    int preset_line = 0;
    std::vector<KnobSpec> knobs;               // `[[knob]]` tables
    std::vector<ScheduleEntry> schedule;       // `[[schedule]]` tables, in file order
    std::optional<ScheduleLocation> location;  // `[location]`, required when an entry uses sunrise or sunset
    // The saved state's top-level `remote = ["rain.intensity"]`: which of its values came from MQTT
    // rather than a knob (ParamSource::Remote once restored).
    std::vector<ParamId> remote;
};

// At most this many [[knob]] tables: each holds GPIO lines and a queue of events.
inline constexpr std::size_t max_knobs = 64;

// `path` is used in messages only. The text is checked against toml_limits (toml_limits.hpp) before it is
// parsed.
Result<Config> parse_config(std::string_view text, std::string_view path);
// The file is read with read_toml_file: at most 1 MiB.
Result<Config> load_config_file(const std::string& path);

// For the saved state, which is the user's data: a bad key (unknown, wrong type, out of range, a [[knob]]
// table that does not parse) is left out and reported, one line each in file order, and every valid key
// is kept. Text that stops being TOML at some line keeps the keys before that line (`syntax_error` says
// where). Fails only when no key can be trusted: past the input limits, or not TOML from line 1.
struct PartialConfig {
    Config config;
    std::vector<std::string> dropped;  // "config: PATH:LINE: unknown key 'rain.wind' (did you mean ...?)"
    // "config: PATH:LINE: rain.seed: Error while parsing ...; the keys from line LINE on are dropped"
    std::optional<std::string> syntax_error;
};
Result<PartialConfig> parse_config_keeping_valid(std::string_view text, std::string_view path);
// Applies every entry with the given source (precedence rules of Params::set apply).
void apply_config(const Config& config, Params& params, ParamSource source = ParamSource::Config);
// `--set name=value`: parse, validate, and name the flag in errors.
Result<ConfigEntry> parse_assignment(std::string_view assignment);

}  // namespace puddle::params
