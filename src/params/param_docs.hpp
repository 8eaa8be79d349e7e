#pragma once
// The registry as text: `puddle --list-params` and the parameter table of docs/parameters.md (a test keeps
// that table equal to format_params_markdown()).

#include <span>
#include <string>

#include "params/param_store.hpp"

namespace puddle::params {

std::string format_params_list();      // one block per parameter, for a terminal
std::string format_params_markdown();  // | name | type | default | range | help |
// `--print-config`: every effective value and where it came from (naming the preset, if any, and the
// schedule entry: `schedule_entries[id]` is N of schedule[N], ParamLayers::schedule_entries()). The header
// names the preset and the presets of the active schedule entries (ParamLayers::active_schedule_presets()).
std::string format_effective(const Params& params, std::string_view preset = {},
                             std::span<const int> schedule_entries = {},
                             std::span<const std::string> schedule_presets = {});

}  // namespace puddle::params
