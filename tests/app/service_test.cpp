// Running as a systemd service: the notify protocol (READY, watchdog pings only while frames are
// presented), journal-friendly log lines, and the unit and sysusers files systemd itself accepts.
#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <spdlog/spdlog.h>

#include "app/logging.hpp"
#include "app/service_notify.hpp"
#include "support/test_support.hpp"

namespace puddle::app {
namespace {

// The systemd side of the notify protocol: a datagram socket the test listens on.
class NotifyListener {
public:
    explicit NotifyListener(const std::filesystem::path& path) : path_(path.string()) {
        fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path_.c_str());
        ok_ = ::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
    }
    ~NotifyListener() { ::close(fd_); }
    bool ok() const { return ok_; }
    const std::string& path() const { return path_; }
    std::vector<std::string> received() {
        std::vector<std::string> out;
        char buf[512];
        for (ssize_t n; (n = ::recv(fd_, buf, sizeof buf, 0)) > 0;) out.emplace_back(buf, static_cast<std::size_t>(n));
        return out;
    }

private:
    std::string path_;
    int fd_ = -1;
    bool ok_ = false;
};

struct Env {
    Env(const char* name, const std::string& value) : name_(name) { ::setenv(name, value.c_str(), 1); }
    ~Env() { ::unsetenv(name_); }
    const char* name_;
};

// Only whole microseconds above zero are a watchdog period; "-5" had been read as 2^64 - 5 microseconds.
TEST(ServiceNotify, AWatchdogPeriodThatIsNoPositiveWholeNumberMeansNoPings) {
    test::TempDir dir;
    NotifyListener systemd(dir / "notify");
    ASSERT_TRUE(systemd.ok());
    Env socket("NOTIFY_SOCKET", systemd.path());
    for (const char* bad : {"-5", "0", "2s", "", "1e6", "99999999999999999999999"}) {
        Env watchdog("WATCHDOG_USEC", bad);
        EXPECT_EQ(ServiceNotify::from_environment().watchdog_interval(), 0.0) << "WATCHDOG_USEC=" << bad;
    }
    Env watchdog("WATCHDOG_USEC", "250000");
    EXPECT_DOUBLE_EQ(ServiceNotify::from_environment().watchdog_interval(), 0.25);
}

TEST(ServiceNotify, ReadyAfterTheFirstFrameThenPingsOnlyWhileFramesArePresented) {
    test::TempDir dir;
    NotifyListener systemd(dir / "notify");
    ASSERT_TRUE(systemd.ok());
    Env socket("NOTIFY_SOCKET", systemd.path());
    Env watchdog("WATCHDOG_USEC", "2000000");  // 2 s: a ping every half second while frames flow
    ServiceNotify n = ServiceNotify::from_environment();
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
                     static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size())), 0);
    Env socket("NOTIFY_SOCKET", "@" + name);
    ServiceNotify n = ServiceNotify::from_environment();
    n.frame_presented(1.0);
    char buf[64] = {};
    EXPECT_GT(::recv(fd, buf, sizeof buf - 1, 0), 0);
    EXPECT_EQ(std::string(buf).rfind("READY=1", 0), 0u);
    ::close(fd);
}

TEST(ServiceNotify, NotUnderSystemdEverythingIsANoOp) {
    ::unsetenv("NOTIFY_SOCKET");
    ServiceNotify n = ServiceNotify::from_environment();
    EXPECT_FALSE(n.enabled());
    n.frame_presented(1.0);  // must not crash or block
    EXPECT_FALSE(n.enabled());
}

TEST(Logging, UnderTheJournalLinesCarryPrioritiesAndNoColour) {
    test::TempDir dir;
    const std::string path = (dir / "journal.txt").string();
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    FILE* f = std::fopen(path.c_str(), "w");
    ::dup2(::fileno(f), STDERR_FILENO);
    struct stat st {};
    ::fstat(STDERR_FILENO, &st);
    Env stream("JOURNAL_STREAM", std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino));
    const LogStyle style = detect_log_style();
    spdlog::drop("puddle");
    setup_logging(style);
    spdlog::info("started: headless");
    spdlog::warn("gpio: gpiochip0 line 17: busy");
    spdlog::error("config: a.toml:3: bad");
    spdlog::default_logger()->flush();
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::fclose(f);
    spdlog::drop("puddle");
    EXPECT_EQ(style, LogStyle::Journal);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "<6>started: headless\n<4>gpio: gpiochip0 line 17: busy\n<3>config: a.toml:3: bad\n");
}

TEST(Logging, AFileOrPipeGetsPlainLevelsWithoutEscapeCodes) {
    ::unsetenv("JOURNAL_STREAM");
    test::TempDir dir;
    const std::string path = (dir / "log.txt").string();
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    FILE* f = std::fopen(path.c_str(), "w");
    ::dup2(::fileno(f), STDERR_FILENO);
    const LogStyle style = detect_log_style();
    spdlog::drop("puddle");
    setup_logging(style);
    spdlog::warn("something");
    spdlog::default_logger()->flush();
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    std::fclose(f);
    spdlog::drop("puddle");
    EXPECT_EQ(style, LogStyle::Plain);
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "warning: something\n");
}

TEST(Deploy, SystemdAcceptsTheUnit) {
    if (std::system("command -v systemd-analyze >/dev/null 2>&1") != 0) GTEST_SKIP() << "systemd-analyze is not installed";
    test::TempDir dir;
    std::ifstream in(std::string(PUDDLE_SOURCE_DIR) + "/deploy/puddle.service");
    std::stringstream unit;
    unit << in.rdbuf();
    std::string text = unit.str();
    // The unit names the installed binary; verify it against the one just built.
    const auto at = text.find("/usr/bin/puddle");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, std::string("/usr/bin/puddle").size(), PUDDLE_BINARY);
    for (const char* key : {"Type=notify", "WatchdogSec=", "Restart=always", "StateDirectory=puddle",
                            "ConfigurationDirectory=puddle", "NoNewPrivileges=yes", "ProtectSystem=strict",
                            "ProtectHome=yes", "PrivateTmp=yes", "SupplementaryGroups=video render input gpio",
                            "TTYPath=/dev/tty"})
        EXPECT_NE(text.find(key), std::string::npos) << key;
    const std::string path = dir.write("puddle.service", text);
    const auto verify = test::run_command("systemd-analyze verify " + path);
    EXPECT_EQ(verify.exit_code, 0) << verify.output;
    EXPECT_EQ(verify.output.find("puddle.service"), std::string::npos) << "no complaint about the unit:\n"
                                                                       << verify.output;
}

TEST(Deploy, SysusersCreatesTheUserInItsGroups) {
    if (std::system("command -v systemd-sysusers >/dev/null 2>&1") != 0) GTEST_SKIP() << "systemd-sysusers is not installed";
    test::TempDir root;
    std::filesystem::create_directories(root / "etc");
    // A root with the groups a Debian system has.
    std::ofstream(root / "etc" / "group") << "root:x:0:\nvideo:x:44:\ninput:x:105:\nrender:x:106:\n";
    std::ofstream(root / "etc" / "passwd") << "root:x:0:0:root:/root:/bin/sh\n";
    const std::string cmd = "systemd-sysusers --root=" + root.path().string() + " " + PUDDLE_SOURCE_DIR +
                            "/deploy/puddle.sysusers 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream passwd(root / "etc" / "passwd"), group(root / "etc" / "group");
    std::stringstream p, g;
    p << passwd.rdbuf();
    g << group.rdbuf();
    EXPECT_NE(p.str().find("puddle:x:"), std::string::npos) << p.str();
    EXPECT_NE(g.str().find("gpio:x:"), std::string::npos) << g.str();
    for (const char* grp : {"video:x:44:puddle", "input:x:105:puddle", "render:x:106:puddle"})
        EXPECT_NE(g.str().find(grp), std::string::npos) << grp << "\n" << g.str();
}

}  // namespace
}  // namespace puddle::app
