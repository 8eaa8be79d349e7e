#pragma once
// The rule of the [wall] section that no one key's range can say: this screen's column and row lie
// inside the wall, 0-based (wall.column 0 to wall.columns - 1, wall.row 0 to wall.rows - 1).
// ParamLayers::set_config applies it to the preset, the config and the command line together before it
// takes a config (start-up, --check, reloads: a bad reload keeps the last good config), and start-up
// without a config file to the command line. The message names where the position was set:
//   config: /etc/puddle/puddle.toml:7: wall.column = 2 is out of range: allowed 0 to 1 (0-based; wall.columns
//   = 2)
//   --set wall.column=2: wall.column = 2 is out of range: allowed 0 to 1 (0-based; wall.columns = 2)
// Knob and broker values are not refused here; render::wall_window clamps them to the wall.

#include "params/config_loader.hpp"
#include "params/param_store.hpp"
#include "util/result.hpp"

namespace puddle::params {

// `params`: the composed values; `config`: the config file they include, for its line numbers.
Result<void> check_wall(const Params& params, const Config& config);

}  // namespace puddle::params
