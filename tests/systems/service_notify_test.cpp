// The systemd notify protocol (systems/service/service_notify.hpp): READY after the first frame, watchdog
// pings only while frames are presented, abstract socket names, and nothing at all outside systemd.
#include "systems/service/service_notify.hpp"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/notify_listener.hpp"
#include "support/test_support.hpp"

namespace puddle::app {
namespace {

using test::NotifyListener;

// Only whole microseconds above zero are a watchdog period; "-5" had been read as 2^64 - 5 microseconds.
TEST(ServiceNotify, AWatchdogPeriodThatIsNoPositiveWholeNumberMeansNoPings) {
    test::TempDir dir;
    NotifyListener systemd(dir / "notify");
    ASSERT_TRUE(systemd.ok());
    test::ScopedEnv socket("NOTIFY_SOCKET", systemd.path());
    for (const char* bad : {"-5", "0", "2s", "", "1e6", "99999999999999999999999"}) {
        test::ScopedEnv watchdog("WATCHDOG_USEC", bad);
        EXPECT_EQ(systems::ServiceNotify::from_environment().watchdog_interval(), 0.0)
            << "WATCHDOG_USEC=" << bad;
    }
    test::ScopedEnv watchdog("WATCHDOG_USEC", "250000");
    EXPECT_DOUBLE_EQ(systems::ServiceNotify::from_environment().watchdog_interval(), 0.25);
}

TEST(ServiceNotify, ReadyAfterTheFirstFrameThenPingsOnlyWhileFramesArePresented) {
    test::TempDir dir;
    NotifyListener systemd(dir / "notify");
    ASSERT_TRUE(systemd.ok());
    test::ScopedEnv socket("NOTIFY_SOCKET", systemd.path());
    test::ScopedEnv watchdog("WATCHDOG_USEC", "2000000");  // 2 s: a ping every half second while frames flow
    systems::ServiceNotify n = systems::ServiceNotify::from_environment();
    ASSERT_TRUE(n.enabled());
    EXPECT_DOUBLE_EQ(n.watchdog_interval(), 2.0);
    EXPECT_TRUE(systemd.received().empty()) << "nothing before a frame was shown";

    n.frame_presented(100.0);
    auto first = systemd.received();
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].rfind("READY=1", 0), 0u) << first[0];

    for (double t = 100.0; t < 103.0; t += 1.0 / 60) n.frame_presented(t);  // 3 s of frames
    auto pings = systemd.received();
    EXPECT_GE(pings.size(), 5u) << "a quarter of the period apart: one slow frame still leaves half of it";
    EXPECT_LE(pings.size(), 6u) << "rate-limited to a quarter of the watchdog period, not one per frame";
    for (const auto& p : pings) EXPECT_EQ(p, "WATCHDOG=1");

    // The loop stalls (a hung GPU): no frames, so no pings, and systemd will restart the service.
    EXPECT_TRUE(systemd.received().empty());
    n.frame_presented(110.0);  // frames flow again: a ping at once
    EXPECT_EQ(systemd.received().size(), 1u);
    n.stopping();
    auto last = systemd.received();
    ASSERT_EQ(last.size(), 1u);
    EXPECT_EQ(last[0], "STOPPING=1");
}

TEST(ServiceNotify, AbstractSocketNamesWork) {
    // systemd may give "@name": the abstract namespace, where the name starts with a NUL byte.
    const std::string name = "puddle-test-" + std::to_string(::getpid());
    int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path + 1, name.data(), name.size());
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr),
                     static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size())),
              0);
    test::ScopedEnv socket("NOTIFY_SOCKET", "@" + name);
    systems::ServiceNotify n = systems::ServiceNotify::from_environment();
    n.frame_presented(1.0);
    char buf[64] = {};
    EXPECT_GT(::recv(fd, buf, sizeof buf - 1, 0), 0);
    EXPECT_EQ(std::string(buf).rfind("READY=1", 0), 0u);
    ::close(fd);
}

TEST(ServiceNotify, NotUnderSystemdEverythingIsANoOp) {
    ::unsetenv("NOTIFY_SOCKET");
    systems::ServiceNotify n = systems::ServiceNotify::from_environment();
    EXPECT_FALSE(n.enabled());
    n.frame_presented(1.0);  // must not crash or block
    EXPECT_FALSE(n.enabled());
}

}  // namespace
}  // namespace puddle::app
