#pragma once
// The service around the display, as systems: the reload signal a kiosk is sent and systemd's notify
// protocol (systems/service/service_notify.hpp).
//   input:   reload signal     SIGHUP (as the program reads it, app/signals.hpp) asks live tuning to read
//                              the config again
//   present: watchdog ping     READY=1 after the first presented frame, then WATCHDOG=1, only while
//                              frames really are presented (a failed present sends nothing)
//   exit:    service stopping  STOPPING=1
// SIGINT and SIGTERM are not systems: the program's run loop reads them and stops.

#include <functional>
#include <memory>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "systems/display/display_plugin.hpp"
#include "systems/service/service_notify.hpp"
#include "systems/tuning/tuning_request.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource: how the program hands over a reload signal: true once per SIGHUP received.
struct ReloadSignal {
    std::function<bool()> take;
};

void reload_signal_system(ReloadSignal& signal, TuningInbox& inbox);
void watchdog_ping_system(ServiceNotify& service, const PresentStatus& presented);
void service_stopping_system(ServiceNotify& service);

// Inserts `reload`, `service` and (when absent) the TuningInbox as resources and registers the systems
// above. The reload signal is a request in the inbox, which live tuning (systems::add_live_tuning) acts on.
Result<void> add_service_plugin(ecs::World& world, ecs::Schedule& schedule, ReloadSignal reload,
                                ServiceNotify service);

}  // namespace puddle::systems
