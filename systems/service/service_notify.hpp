#pragma once
// The systemd notify protocol (sd_notify), spoken directly: one datagram per message to the socket in
// $NOTIFY_SOCKET. READY=1 goes out after the first presented frame; WATCHDOG=1 only when frames are
// really presented, at most every quarter of the watchdog period, so a hung GPU or display stops the
// pings and systemd restarts the service. A quarter, not the half sd_watchdog_enabled(3) suggests: then
// the gap between pings stays under half the period even when one frame takes up to a quarter of it.
// Without $NOTIFY_SOCKET (not under systemd) every call does nothing.

#include <string>
#include <string_view>

#include "util/unique_fd.hpp"

namespace puddle::systems {

class ServiceNotify {
public:
    // Reads NOTIFY_SOCKET and WATCHDOG_USEC (and WATCHDOG_PID, which must be ours or unset).
    static ServiceNotify from_environment();
    ServiceNotify() = default;

    bool enabled() const { return static_cast<bool>(fd_); }
    double watchdog_interval() const { return watchdog_seconds_; }  // 0: no watchdog
    double ping_interval() const { return watchdog_seconds_ / 4; }  // the least time between pings

    // Called after each presented frame at monotonic time `now`: READY=1 the first time, then
    // WATCHDOG=1 whenever ping_interval() has passed since the last ping.
    void frame_presented(double now);
    // STATUS=... (shown by systemctl status) and STOPPING=1.
    void status(std::string_view text);
    void stopping();

private:
    bool send(std::string_view message);
    UniqueFd fd_;          // the datagram socket; none without $NOTIFY_SOCKET
    std::string address_;  // the socket path; a leading '@' is the abstract namespace
    double watchdog_seconds_ = 0;
    bool ready_sent_ = false;
    double last_ping_ = -1e9;
};

}  // namespace puddle::systems
