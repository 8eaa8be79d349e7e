#pragma once
// The puddle program: options -> parameters -> engine -> frame loop. Returns the process exit code.

#include <memory>
#include <vector>

#include "app/cli.hpp"
#include "app/engine.hpp"
#include "app/service_notify.hpp"
#include "app/signals.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "util/result.hpp"

namespace puddle::app {

int run(int argc, const char* const* argv);

// The layers of live tuning the options ask for: defaults < preset < config < knob and remote state <
// --seed/--set, with the config file's path to watch and the knobs' GPIO backend. Errors in the config
// or a flag are exit code 2; bad keys in the state file are dropped and warned about, one line each, and the
// original is set aside (docs/configuration.md, "Saved knob state"). `read_only` (--print-config) reads and
// warns but changes nothing on disk. The soak test builds its engine with this too, so it runs what the
// binary runs.
Result<systems::LiveTuning> load_tuning(const CliOptions& options, bool read_only = false);
// Where presets are read from besides the built-in ones: /etc/puddle/presets, then presets/ beside the
// config file (a later folder's preset of the same name wins).
std::vector<std::string> preset_folders_for(const std::string& config_path);

// The features the puddle binary installs, in this order: the service (signals, systemd), live tuning,
// the puddle, remote control (MQTT; nothing unless [remote] asks for it). The plugins take their arguments
// over (moved from) when Engine::create runs them.
std::vector<Engine::Plugin> puddle_features(std::unique_ptr<StopSignals>& signals, ServiceNotify& service,
                                            systems::LiveTuning& tuning);

}  // namespace puddle::app
