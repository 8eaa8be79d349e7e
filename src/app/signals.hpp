#pragma once
// SIGINT/SIGTERM (stop) and SIGHUP (reload the config) as a file descriptor (signalfd), polled by the
// frame loop: a clean stop needs no global flag and no work inside a signal handler.
//
// The three are blocked from the first statement of main (block_stop_signals), not only once the
// StopSignals exists: a config-management tool sends SIGHUP right after a (re)start, and SIGHUP's default
// action ends the process (exit 129). Blocked, a signal waits (pending) and the signalfd reads it then.

#include <csignal>
#include <utility>

#include "util/unique_fd.hpp"

namespace puddle::app {

// The first statement of main: blocks SIGINT, SIGTERM and SIGHUP for the process (every thread started
// later inherits the mask), so one sent while Puddle starts is pending until a StopSignals reads it.
void block_stop_signals();
// For a command that ends by itself (--check, --print-config, --list-params): SIGHUP (a reload) is ignored,
// and SIGINT and SIGTERM end it as usual again (one that was pending is delivered now).
void release_stop_signals_for_one_shot();

class StopSignals {
public:
    StopSignals();  // blocks SIGINT, SIGTERM and SIGHUP for this thread and opens the signalfd; one that
                    // was pending already (blocked since main began) is read from it too
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;
    // True once SIGINT or SIGTERM arrived; never blocks.
    bool requested();
    // True once per SIGHUP received since the last call.
    bool take_reload() { return requested(), std::exchange(reload_, false); }
    int last_signal() const { return last_; }

private:
    UniqueFd fd_;  // the signalfd; none when it could not be made
    int last_ = 0;
    bool reload_ = false;
    sigset_t previous_{};
};

}  // namespace puddle::app
