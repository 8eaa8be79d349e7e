#include "systems/service/service_notify.hpp"

#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace puddle::systems {

ServiceNotify ServiceNotify::from_environment() {
    ServiceNotify n;
    const char* socket_path = std::getenv("NOTIFY_SOCKET");
    if (!socket_path || !*socket_path || std::strlen(socket_path) >= sizeof(sockaddr_un::sun_path)) return n;
    n.address_ = socket_path;
    // Non-blocking: if systemd is slow to read, a ping is dropped rather than a frame stalled.
    n.fd_.reset(::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0));
    if (!n.fd_) {
        spdlog::warn("systemd: cannot open the notify socket: {}", std::strerror(errno));
        return n;
    }
    const char* usec = std::getenv("WATCHDOG_USEC");
    const char* pid = std::getenv("WATCHDOG_PID");
    const bool ours = !pid || std::strtol(pid, nullptr, 10) == ::getpid();
    if (usec && ours) {
        // Whole microseconds, above zero, as sd_watchdog_enabled(3) accepts; strtoull took "-5" as 2^64 - 5.
        const std::string_view text(usec);
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc() && end == text.data() + text.size() && value > 0)
            n.watchdog_seconds_ = static_cast<double>(value) * 1e-6;
        else
            spdlog::warn(
                "systemd: WATCHDOG_USEC={} is not a whole number of microseconds above 0; no watchdog pings",
                text);
    }
    return n;
}

bool ServiceNotify::send(std::string_view message) {
    if (!fd_) return false;
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path, address_.data(), address_.size());
    if (addr.sun_path[0] == '@') addr.sun_path[0] = '\0';  // abstract socket
    const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + address_.size());
    return ::sendto(fd_.get(), message.data(), message.size(), MSG_NOSIGNAL,
                    reinterpret_cast<const sockaddr*>(&addr), len) == static_cast<ssize_t>(message.size());
}

void ServiceNotify::frame_presented(double now) {
    if (!fd_) return;
    if (!ready_sent_) {
        ready_sent_ = true;
        last_ping_ = now;
        send("READY=1\nSTATUS=Showing frames");
        return;
    }
    if (watchdog_seconds_ > 0 && now - last_ping_ >= ping_interval()) {
        last_ping_ = now;
        send("WATCHDOG=1");
    }
}

void ServiceNotify::status(std::string_view text) {
    if (!fd_) return;
    std::string m = "STATUS=";
    m += text;
    send(m);
}

void ServiceNotify::stopping() {
    send("STOPPING=1");
}

}  // namespace puddle::systems
