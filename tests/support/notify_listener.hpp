#pragma once
// The systemd side of the notify protocol (sd_notify): a datagram socket a test binds and reads, to see
// what Puddle sent (READY=1, WATCHDOG=1, STOPPING=1...).

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace puddle::test {

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
    NotifyListener(const NotifyListener&) = delete;
    NotifyListener& operator=(const NotifyListener&) = delete;
    bool ok() const { return ok_; }
    const std::string& path() const { return path_; }
    // Every message received since the last call, in order; never waits.
    std::vector<std::string> received() {
        std::vector<std::string> out;
        char buf[512];
        for (ssize_t n; (n = ::recv(fd_, buf, sizeof buf, 0)) > 0;)
            out.emplace_back(buf, static_cast<std::size_t>(n));
        return out;
    }

private:
    std::string path_;
    int fd_ = -1;
    bool ok_ = false;
};

}  // namespace puddle::test
