#include "app/process_setup.hpp"

#include <execinfo.h>
#include <malloc.h>
#include <unistd.h>

#include <csignal>
#include <initializer_list>

namespace puddle::app {

namespace {

// A crash leaves one line and the return addresses on stderr (the journal, under systemd), so a report
// from the field can be turned into file:line with addr2line; then the default action runs (a core dump
// where enabled, and the exit status of the signal for systemd's restart). Only async-signal-safe calls:
// write(2) and backtrace_symbols_fd, whose libgcc is loaded at setup by a first backtrace().
void report_crash(int signal) {
    static constexpr char line[] = "puddle: crashed (fatal signal); return addresses follow:\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, line, sizeof line - 1);
    void* frames[48];
    backtrace_symbols_fd(frames, backtrace(frames, 48), STDERR_FILENO);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void setup_process() {
    void* warm[1];
    (void)backtrace(warm, 1);  // loads libgcc now: not safe to do inside the handler
    for (const int fatal : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT}) std::signal(fatal, report_crash);
    std::signal(SIGPIPE, SIG_IGN);
    mallopt(M_ARENA_MAX, 1);
    // Fixed thresholds: glibc otherwise raises both after a large block is freed (up to 32 MiB), and then
    // keeps freed memory instead of returning it, so resident memory creeps after a sky or camera load.
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
    mallopt(M_TRIM_THRESHOLD, 512 * 1024);
}

}  // namespace puddle::app
