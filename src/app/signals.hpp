#pragma once
// SIGINT/SIGTERM (stop) and SIGHUP (reload the config) as a file descriptor (signalfd), polled by the
// frame loop: a clean stop needs no global flag and no work inside a signal handler.

#include <csignal>
#include <utility>

#include "util/unique_fd.hpp"

namespace puddle::app {

class StopSignals {
public:
    StopSignals();  // blocks SIGINT and SIGTERM for this thread and opens the signalfd
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
