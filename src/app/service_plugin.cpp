#include "app/service_plugin.hpp"

#include "util/monotonic_clock.hpp"

namespace puddle::app {

void reload_signal_system(StopSignals& signals, systems::TuningInbox& inbox) {
    if (signals.take_reload()) inbox.push(systems::ReloadConfig{"SIGHUP"});
}

void watchdog_ping_system(ServiceNotify& service, const systems::PresentStatus& presented) {
    if (presented.result) service.frame_presented(monotonic_seconds());
}

void service_stopping_system(ServiceNotify& service) {
    service.stopping();
}

Result<void> add_service_plugin(ecs::World& world, ecs::Schedule& schedule,
                                std::unique_ptr<StopSignals> signals, ServiceNotify service) {
    world.adopt_resource<StopSignals>(std::move(signals));
    world.insert_resource<ServiceNotify>(std::move(service));
    if (!world.try_resource<systems::TuningInbox>()) world.insert_resource<systems::TuningInbox>();
    using ecs::Stage;
    schedule.add(Stage::Input, "reload signal", reload_signal_system);
    schedule.add(Stage::Present, "watchdog ping", watchdog_ping_system);
    schedule.add(Stage::Exit, "service stopping", service_stopping_system);
    return {};
}

}  // namespace puddle::app
