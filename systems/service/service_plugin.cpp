#include "systems/service/service_plugin.hpp"

#include "util/monotonic_clock.hpp"

namespace puddle::systems {

void reload_signal_system(ReloadSignal& signal, TuningInbox& inbox) {
    if (signal.take && signal.take()) inbox.push(ReloadConfig{"SIGHUP"});
}

void watchdog_ping_system(ServiceNotify& service, const PresentStatus& presented) {
    if (presented.result) service.frame_presented(monotonic_seconds());
}

void service_stopping_system(ServiceNotify& service) {
    service.stopping();
}

Result<void> add_service_plugin(ecs::World& world, ecs::Schedule& schedule, ReloadSignal reload,
                                ServiceNotify service) {
    world.insert_resource<ReloadSignal>(std::move(reload));
    world.insert_resource<ServiceNotify>(std::move(service));
    if (!world.try_resource<TuningInbox>()) world.insert_resource<TuningInbox>();
    using ecs::Stage;
    schedule.add(Stage::Input, "reload signal", reload_signal_system);
    schedule.add(Stage::Present, "watchdog ping", watchdog_ping_system);
    schedule.add(Stage::Exit, "service stopping", service_stopping_system);
    return {};
}

}  // namespace puddle::systems
