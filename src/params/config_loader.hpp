#pragma once
// The TOML config: `[section]` tables whose keys are the registry's names (`[rain] drop_count = 20`
// is rain.drop_count), an optional top-level `preset = "name"`, and `[[knob]]` tables. Presets and the
// saved state use the same format. A file is validated completely before anything is applied; the
// first problem is reported with file:line, the key, the value and what is allowed.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "params/knob_spec.hpp"
#include "params/param_store.hpp"
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
    std::vector<KnobSpec> knobs;        // `[[knob]]` tables
};

// `path` is used in messages only.
Result<Config> parse_config(std::string_view text, std::string_view path);
Result<Config> load_config_file(const std::string& path);
// Applies every entry with the given source (precedence rules of Params::set apply).
void apply_config(const Config& config, Params& params, ParamSource source = ParamSource::Config);
// `--set name=value`: parse, validate, and name the flag in errors.
Result<ConfigEntry> parse_assignment(std::string_view assignment);

}  // namespace puddle::params
