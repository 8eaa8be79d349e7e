// Tests for src/app/process_setup.hpp: after setup_process(), threads that allocate share one malloc
// arena, a freed large block does not raise the mmap or trim thresholds, and a write to a closed pipe
// fails with EPIPE instead of ending the process. Checked in a fresh process (process_setup_probe.cpp),
// beside a control run without the setup that shows glibc's defaults differ, so each check can fail.
#include "app/process_setup.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <map>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace puddle::app {
namespace {

struct ProbeReport {
    std::map<std::string, std::string> values;
    std::string output;
    int exit_code = -1;
};

// The probe's `name value` lines. glibc's malloc variables are unset so that both runs start from its
// defaults.
ProbeReport run_probe(const std::string& args) {
    const test::CommandResult r = test::run_command(
        "env -u MALLOC_ARENA_MAX -u MALLOC_MMAP_THRESHOLD_ -u MALLOC_TRIM_THRESHOLD_ -u GLIBC_TUNABLES " +
        test::program_command(PUDDLE_PROCESS_SETUP_PROBE) + " " + args);
    ProbeReport report{.output = r.output, .exit_code = r.exit_code};
    std::istringstream lines(r.output);
    std::string name, value;
    while (lines >> name >> value) report.values[name] = value;
    return report;
}

int number(const ProbeReport& r, const std::string& name) {
    const auto at = r.values.find(name);
    if (at == r.values.end()) {
        ADD_FAILURE() << "the probe did not report " << name << ":\n" << r.output;
        return -1;
    }
    return std::stoi(at->second);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool glibc_malloc = false;  // AddressSanitizer replaces malloc: no arenas, no thresholds
#else
constexpr bool glibc_malloc = true;
#endif

TEST(ProcessSetup, ThreadsThatAllocateShareOneArena) {
    if (!glibc_malloc) GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc";
    const ProbeReport setup = run_probe("setup");
    EXPECT_EQ(number(setup, "heaps_before"), 1) << setup.output;
    EXPECT_EQ(number(setup, "heaps_with_threads"), 1) << setup.output;
    const ProbeReport control = run_probe("");
    EXPECT_EQ(number(control, "heaps_with_threads"), number(control, "heaps_before") + 4)
        << "glibc's default, an arena per thread: " << control.output;
}

TEST(ProcessSetup, AFreedLargeBlockRaisesNeitherThreshold) {
    if (!glibc_malloc) GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc";
    const ProbeReport setup = run_probe("setup");
    EXPECT_EQ(number(setup, "mmapped_after_large_free"), 1) << "1 MiB is over the fixed 256 KiB:\n"
                                                            << setup.output;
    EXPECT_LT(number(setup, "kept_kib_after_free"), 512)
        << "2 MiB freed is over the 512 KiB trim threshold:\n"
        << setup.output;
    const ProbeReport control = run_probe("");
    EXPECT_EQ(number(control, "mmapped_after_large_free"), 0)
        << "glibc's default raises the threshold to 4 MiB: " << control.output;
    EXPECT_GT(number(control, "kept_kib_after_free"), 1024) << "and keeps what is freed: " << control.output;
}

TEST(ProcessSetup, AWriteToAClosedPipeFailsWithEpipe) {
    ProbeReport setup = run_probe("setup");
    EXPECT_EQ(setup.exit_code, 0) << setup.output;
    EXPECT_EQ(setup.values["closed_pipe_write"], "EPIPE") << setup.output;
    const ProbeReport control = run_probe("");
    EXPECT_NE(control.exit_code, 0) << "SIGPIPE ends a process by default: " << control.output;
    EXPECT_EQ(control.values.count("closed_pipe_write"), 0u) << control.output;
}

// A crash leaves a line and the return addresses on stderr (the journal), then dies of the same signal:
// without the handler the process dies silently.
TEST(ProcessSetupDeathTest, AFatalSignalWritesALineAndTheReturnAddressesThenDiesOfIt) {
#ifdef PUDDLE_TESTS_UNDER_EMULATOR
    GTEST_SKIP() << "under qemu-user (deploy/cross-build.sh --test) the threadsafe death test cannot execute "
                    "the arm64 test binary again; it runs natively on the build machine and on the board";
#endif
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            setup_process();
            std::raise(SIGSEGV);
        },
        ::testing::KilledBySignal(SIGSEGV),
        "puddle: crashed \\(fatal signal\\); return addresses follow:\n.*puddle");
}

}  // namespace
}  // namespace puddle::app
