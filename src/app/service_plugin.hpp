#pragma once
// The service around the display, as systems: the signals a kiosk is run by and systemd's notify
// protocol (app/service_notify.hpp).
//   input:   reload signal     SIGHUP asks live tuning to read the config again
//   present: watchdog ping     READY=1 after the first presented frame, then WATCHDOG=1, only while
//                              frames really are presented (a failed present sends nothing)
//   exit:    service stopping  STOPPING=1
// SIGINT and SIGTERM are not systems: the run loop reads them (StopSignals::requested) and stops.

#include <memory>

#include "app/service_notify.hpp"
#include "app/signals.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "systems/display/display_plugin.hpp"
#include "systems/tuning/tuning_request.hpp"
#include "util/result.hpp"

namespace puddle::app {

void reload_signal_system(StopSignals& signals, systems::TuningInbox& inbox);
void watchdog_ping_system(ServiceNotify& service, const systems::PresentStatus& presented);
void service_stopping_system(ServiceNotify& service);

// Inserts `signals`, `service` and (when absent) the TuningInbox as resources and registers the systems
// above. The reload signal is a request in the inbox, which live tuning (systems::add_live_tuning) acts on.
Result<void> add_service_plugin(ecs::World& world, ecs::Schedule& schedule,
                                std::unique_ptr<StopSignals> signals, ServiceNotify service);

}  // namespace puddle::app
