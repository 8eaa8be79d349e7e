// Signals sent while the puddle binary starts (app/signals.hpp): a config-management tool sends SIGHUP
// right after a (re)start, before the frame loop's StopSignals exists. The binary is started and signalled
// 5 to 30 ms later, twice each: SIGHUP must never end it (its default action did: exit 129, 8 of 8 runs at
// 5 ms, 4 of 12 at 10 to 30 ms), and SIGTERM or SIGINT must be a clean stop (an exit, not death by the
// signal). Earlier than about 5 ms the signal can arrive while the dynamic loader still maps the libraries,
// before main's first instruction: no code of the program runs yet there, so that window is not tested.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

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

// The binary's wait status after `sig` was sent `delay` after it was started.
int status_after_signal(const std::vector<std::string>& args, int sig, std::chrono::microseconds delay) {
    std::vector<std::string> all{PUDDLE_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, PUDDLE_BINARY, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    EXPECT_EQ(spawned, 0) << std::strerror(spawned);
    if (spawned != 0) return -1;
    std::this_thread::sleep_for(delay);
    ::kill(pid, sig);
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

constexpr int delays_ms[] = {5, 10, 15, 20, 30};

TEST_F(StartupSignals, ASighupInTheFirstMillisecondsIsNoStop) {
    for (int rep = 0; rep < 2; ++rep)
        for (const int ms : delays_ms) {
            const int status = status_after_signal(args, SIGHUP, std::chrono::milliseconds(ms));
            EXPECT_FALSE(WIFSIGNALED(status) && WTERMSIG(status) == SIGHUP)
                << "SIGHUP " << ms << " ms after the start: " << describe(status);
        }
}

TEST_F(StartupSignals, ASigtermOrSigintInTheFirstMillisecondsIsACleanStop) {
    for (const int sig : {SIGTERM, SIGINT})
        for (const int ms : delays_ms) {
            const int status = status_after_signal(args, sig, std::chrono::milliseconds(ms));
            EXPECT_TRUE(WIFEXITED(status))
                << strsignal(sig) << " " << ms << " ms after the start: " << describe(status);
        }
}

}  // namespace
}  // namespace puddle::app
