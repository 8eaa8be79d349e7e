// The real binary under a systemd-like notify socket: READY once a frame is shown, watchdog pings
// while frames flow, STOPPING at the end.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

TEST(ServiceEndToEnd, NotifiesReadyPingsTheWatchdogAndSaysStopping) {
    TempDir dir;
    const std::string path = (dir / "notify").string();
    const int fd = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path.c_str());
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);

    // A 20 ms watchdog: pings every 5 ms of frames; 60 frames take longer than that.
    const std::string cmd = "NOTIFY_SOCKET=" + path + " WATCHDOG_USEC=20000 " + PUDDLE_BINARY +
                            " -b headless --size 64x36 --frames 60";
    // Read the socket while the binary runs, as systemd does (its queue holds only a few datagrams).
    std::vector<std::string> got;
    std::atomic<bool> done{false};
    std::thread listener([&] {
        char msg[512];
        while (!done) {
            const ssize_t n = ::recv(fd, msg, sizeof msg, 0);
            if (n > 0)
                got.emplace_back(msg, static_cast<std::size_t>(n));
            else
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        for (ssize_t n; (n = ::recv(fd, msg, sizeof msg, 0)) > 0;)
            got.emplace_back(msg, static_cast<std::size_t>(n));
    });
    const CommandResult run = run_command(cmd);
    done = true;
    listener.join();
    ::close(fd);
    const std::string& out = run.output;
    ASSERT_EQ(run.exit_code, 0) << out;
    ASSERT_GE(got.size(), 3u) << out;
    EXPECT_EQ(got.front().rfind("READY=1", 0), 0u) << got.front();
    EXPECT_EQ(got.back(), "STOPPING=1");
    for (std::size_t i = 1; i + 1 < got.size(); ++i) EXPECT_EQ(got[i], "WATCHDOG=1");
    EXPECT_NE(out.find("systemd: READY after the first frame, watchdog every 0.005 s"), std::string::npos)
        << out;
}

}  // namespace
}  // namespace puddle::test
