#pragma once
// The puddle program: options -> parameters -> engine -> frame loop. Returns the process exit code.

#include <memory>
#include <vector>

#include "app/cli.hpp"
#include "app/engine.hpp"
#include "app/signals.hpp"
#include "app/startup.hpp"
#include "systems/service/service_notify.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "util/result.hpp"

namespace puddle::app {

int run(int argc, const char* const* argv);

// The features the puddle binary installs, in this order: the service (signals, systemd), live tuning,
// the puddle, remote control (MQTT; nothing unless [remote] asks for it). The plugins take their arguments
// over (moved from) when Engine::create runs them.
std::vector<Engine::Plugin> puddle_features(std::unique_ptr<StopSignals>& signals,
                                            systems::ServiceNotify& service, systems::LiveTuning& tuning);

}  // namespace puddle::app
