// The service plugin's systems (systems/service/service_plugin.hpp) in a schedule of their own: SIGHUP
// reaches live tuning as a reload, the watchdog is pinged only after a frame was really presented, and the
// exit stage says STOPPING=1, each seen on a real notify socket.
#include "systems/service/service_plugin.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "app/signals.hpp"
#include "params/presets.hpp"
#include "support/notify_listener.hpp"
#include "support/test_support.hpp"

namespace puddle::app {
namespace {

struct Rig {
    test::TempDir dir;
    test::NotifyListener systemd{dir / "notify"};
    StopSignals signals;  // the program's, as app.cpp hands its reload signal over
    ecs::World world;
    ecs::Schedule schedule;

    Rig() {
        test::ScopedEnv socket("NOTIFY_SOCKET", systemd.path());
        test::ScopedEnv watchdog("WATCHDOG_USEC", "4000");  // pings at most every millisecond
        world.insert_resource<systems::PresentStatus>();
        auto added = systems::add_service_plugin(world, schedule, {[this] { return signals.take_reload(); }},
                                                 systems::ServiceNotify::from_environment());
        EXPECT_TRUE(added.ok());
    }
};

TEST(ServicePlugin, RegistersItsThreeSystemsInTheirStages) {
    Rig rig;
    EXPECT_EQ(rig.schedule.describe(),
              (std::vector<std::string>{
                  "input/reload signal (writes ReloadSignal, TuningInbox)",
                  "present/watchdog ping (reads PresentStatus; writes ServiceNotify)",
                  "exit/service stopping (writes ServiceNotify)",
              }));
}

TEST(ServicePlugin, SighupAsksLiveTuningToReloadOnce) {
    Rig rig;
    auto& inbox = rig.world.resource<systems::TuningInbox>();
    rig.schedule.run_stage(ecs::Stage::Input, rig.world);
    EXPECT_TRUE(inbox.requests.empty());
    ASSERT_EQ(raise(SIGHUP), 0);  // blocked by StopSignals: read from its fd, never delivered
    rig.schedule.run_stage(ecs::Stage::Input, rig.world);
    ASSERT_EQ(inbox.requests.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<systems::ReloadConfig>(inbox.requests[0]));
    inbox.requests.clear();  // as live tuning's step does
    rig.schedule.run_stage(ecs::Stage::Input, rig.world);
    EXPECT_TRUE(inbox.requests.empty()) << "one SIGHUP is one reload";
}

TEST(ServicePlugin, TheWatchdogIsPingedOnlyAfterAPresentedFrameAndStoppingAtExit) {
    Rig rig;
    auto& presented = rig.world.resource<systems::PresentStatus>();
    presented.result = make_error(ExitCode::Display, "display: page flip failed");
    rig.schedule.run_stage(ecs::Stage::Present, rig.world);
    EXPECT_EQ(rig.systemd.received(), std::vector<std::string>{}) << "a failed present sends nothing";

    presented.result = {};
    rig.schedule.run_stage(ecs::Stage::Present, rig.world);
    EXPECT_EQ(rig.systemd.received(), std::vector<std::string>{"READY=1\nSTATUS=Showing frames"});
    std::this_thread::sleep_for(std::chrono::milliseconds(10));  // past the ping interval (a quarter of 4 ms)
    rig.schedule.run_stage(ecs::Stage::Present, rig.world);
    EXPECT_EQ(rig.systemd.received(), std::vector<std::string>{"WATCHDOG=1"});

    rig.schedule.run_exit(rig.world);
    EXPECT_EQ(rig.systemd.received(), std::vector<std::string>{"STOPPING=1"});
}

}  // namespace
}  // namespace puddle::app
