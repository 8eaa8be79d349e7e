#pragma once
// Start-up's one assembly of the parameters: the preset folders, the config file, the schedule active now,
// the saved knob and remote state and the knobs' GPIO, as the binary runs them. The run, --print-config,
// --check and the soak test all call load_tuning, so each sees what the others do.

#include <string>
#include <vector>

#include "app/cli.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "util/result.hpp"

namespace puddle::app {

// What the parameters are assembled for.
enum class StartFor {
    run,           // the display: everything, the saved state repaired on disk when it had bad keys
    print_config,  // reads the saved state and warns, writes nothing; no GPIO
    check,         // --check: no saved state (it reports on the file itself) and no GPIO
};

// The config file in effect: --config, else /etc/puddle/puddle.toml when it exists, else none ("").
std::string config_path(const CliOptions& options);
// Where presets are read from besides the built-in ones: /etc/puddle/presets, then presets/ beside the
// config file (a later folder's preset of the same name wins).
std::vector<std::string> preset_folders_for(const std::string& config_path);

// The layers of live tuning the options ask for: defaults < preset < config < knob and remote state <
// --seed/--set, with the config file's path to watch and the knobs' GPIO backend. Errors in the config, a
// flag or the GPIO spec are exit code 2 (a GPIO chip that cannot be opened is its own error); bad keys in
// the state file are dropped and warned about, one line each, and the original is set aside
// (docs/configuration.md, "Saved knob state").
Result<systems::LiveTuning> load_tuning(const CliOptions& options, StartFor purpose = StartFor::run);

}  // namespace puddle::app
