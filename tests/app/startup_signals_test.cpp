// Signals sent while the puddle binary starts (app/signals.hpp): a config-management tool sends SIGHUP
// right after a (re)start, before the frame loop's StopSignals exists. The binary is started and signalled
// 0 to 10 ms after its first log line, twice each: SIGHUP must never end it (its default action did: exit
// 129, 8 of 8 runs at 0 to 5 ms after the start), and SIGTERM or SIGINT must be a clean stop (an exit, not
// death by the signal).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

extern char** environ;

namespace puddle::app {
namespace {

// The binary's wait status after `sig` was sent `delay` after its first output. The first output (a log
// line) comes from main, so the signal never lands while the dynamic loader still maps the libraries,
// where no code of the program can run yet; the old code then had the signals unblocked for several ms
// more (the config, the presets, the state file are read before the frame loop's StopSignals).
int status_after_signal(const std::vector<std::string>& args, int sig, std::chrono::microseconds delay) {
    std::vector<std::string> all{PUDDLE_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ADD_FAILURE() << "pipe: " << std::strerror(errno);
        return -1;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, out[1], 2);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, PUDDLE_BINARY, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    EXPECT_EQ(spawned, 0) << std::strerror(spawned);
    if (spawned != 0) {
        ::close(out[0]);
        return -1;
    }
    pollfd ready{out[0], POLLIN, 0};
    ::poll(&ready, 1, 60'000);  // the first log line (or its end)
    std::this_thread::sleep_for(delay);
    ::kill(pid, sig);
    char drain[4096];
    while (::read(out[0], drain, sizeof drain) > 0) {
    }  // to its end, so that it never blocks on a full pipe
    ::close(out[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

std::string describe(int status) {
    if (WIFSIGNALED(status)) return std::string("ended by ") + strsignal(WTERMSIG(status));
    return "exit " + std::to_string(WEXITSTATUS(status));
}

class StartupSignals : public ::testing::Test {
protected:
    void SetUp() override {
#if defined(PUDDLE_TESTS_UNDER_EMULATOR)
        GTEST_SKIP() << "under qemu-user the signal reaches the emulator, not puddle's main";
#endif
    }
    test::TempDir dir;
    std::vector<std::string> args{
        "-b",       "headless", "--size", "32x18",
        "--frames", "2",        "-c",     dir.write("any.toml", "[rain]\ndrop_count = 20\n")};
};

constexpr int delays_ms[] = {0, 1, 2, 5, 10};  // after the first log line

TEST_F(StartupSignals, ASighupInTheFirstMillisecondsIsNoStop) {
    for (int rep = 0; rep < 2; ++rep)
        for (const int ms : delays_ms) {
            const int status = status_after_signal(args, SIGHUP, std::chrono::milliseconds(ms));
            EXPECT_FALSE(WIFSIGNALED(status) && WTERMSIG(status) == SIGHUP)
                << "SIGHUP " << ms << " ms after the first log line: " << describe(status);
        }
}

TEST_F(StartupSignals, ASigtermOrSigintInTheFirstMillisecondsIsACleanStop) {
    for (const int sig : {SIGTERM, SIGINT})
        for (const int ms : delays_ms) {
            const int status = status_after_signal(args, sig, std::chrono::milliseconds(ms));
            EXPECT_TRUE(WIFEXITED(status))
                << strsignal(sig) << " " << ms << " ms after the first log line: " << describe(status);
        }
}

}  // namespace
}  // namespace puddle::app
