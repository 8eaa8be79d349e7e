#include "params/config_watcher.hpp"

#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace puddle::params {

Result<ConfigWatcher> ConfigWatcher::watch(const std::string& path) {
    const std::filesystem::path p = std::filesystem::absolute(path);
    const int fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd < 0) return make_error(ExitCode::Runtime, "config: cannot watch {}: inotify: {}", path, std::strerror(errno));
    constexpr std::uint32_t mask = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM;
    if (inotify_add_watch(fd, p.parent_path().c_str(), mask) < 0) {
        const int err = errno;
        close(fd);
        return make_error(ExitCode::Runtime, "config: cannot watch folder {}: {}", p.parent_path().string(),
                          std::strerror(err));
    }
    return ConfigWatcher(fd, p.filename().string());
}

ConfigWatcher::ConfigWatcher(ConfigWatcher&& other) noexcept : fd_(other.fd_), name_(std::move(other.name_)) {
    other.fd_ = -1;
}

ConfigWatcher& ConfigWatcher::operator=(ConfigWatcher&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) close(fd_);
        fd_ = other.fd_;
        name_ = std::move(other.name_);
        other.fd_ = -1;
    }
    return *this;
}

ConfigWatcher::~ConfigWatcher() {
    if (fd_ >= 0) close(fd_);
}

ConfigWatcher::Change ConfigWatcher::poll() {
    Change change = Change::None;
    alignas(inotify_event) char buffer[4096];
    for (;;) {
        const ssize_t n = read(fd_, buffer, sizeof buffer);
        if (n <= 0) break;  // EAGAIN: nothing more now
        for (ssize_t at = 0; at < n;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
            if (e->len == 0 || name_ != e->name) continue;
            // The last event of a batch tells the state: a write after a removal is a new file.
            if (e->mask & (IN_CLOSE_WRITE | IN_MOVED_TO)) change = Change::Written;
            else if (e->mask & (IN_DELETE | IN_MOVED_FROM)) change = Change::Removed;
        }
    }
    return change;
}

}  // namespace puddle::params
