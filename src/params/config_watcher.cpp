#include "params/config_watcher.hpp"

#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace puddle::params {

namespace fs = std::filesystem;

namespace {

// Creation counts only for a link: a new regular file is complete when it is closed or renamed in.
constexpr std::uint32_t watch_mask = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM | IN_CREATE;
constexpr int max_links = 40;  // as the kernel's ELOOP limit for path resolution

bool is_link(const fs::path& p) {
    std::error_code ec;
    return fs::is_symlink(fs::symlink_status(p, ec));
}

}  // namespace

Result<ConfigWatcher> ConfigWatcher::watch(const std::string& path) {
    const int fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd < 0)
        return make_error(ExitCode::Runtime, "config: cannot watch {}: inotify: {}", path,
                          std::strerror(errno));
    ConfigWatcher w(fd, fs::absolute(path).lexically_normal().string());
    if (auto r = w.rewatch(); !r) return r.error();
    return w;
}

// Follows the chain of links from the path as given and watches the folder of each step. Watches on
// one folder share a descriptor; dropping the old ones first keeps the kernel's count bounded.
Result<void> ConfigWatcher::rewatch() {
    for (const Link& l : chain_)
        inotify_rm_watch(fd_, l.wd);  // a shared descriptor fails the second time: fine
    chain_.clear();
    fs::path p = path_;
    for (int hop = 0; hop <= max_links; ++hop) {
        const fs::path folder = p.parent_path();
        const int wd = inotify_add_watch(fd_, folder.c_str(), watch_mask);
        if (wd < 0)
            return make_error(ExitCode::Runtime, "config: cannot watch folder {}: {}", folder.string(),
                              std::strerror(errno));
        chain_.push_back({wd, folder.string(), p.filename().string()});
        if (!is_link(p)) return {};
        std::error_code ec;
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) return {};  // replaced between the two looks: the next event resolves it again
        p = (folder / target).lexically_normal();
    }
    return make_error(ExitCode::Runtime, "config: {}: more than {} symbolic links in a row", path_,
                      max_links);
}

ConfigWatcher::ConfigWatcher(ConfigWatcher&& other) noexcept
    : fd_(other.fd_), path_(std::move(other.path_)), chain_(std::move(other.chain_)) {
    other.fd_ = -1;
}

ConfigWatcher& ConfigWatcher::operator=(ConfigWatcher&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) close(fd_);
        fd_ = other.fd_;
        path_ = std::move(other.path_);
        chain_ = std::move(other.chain_);
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
            if (e->len == 0) continue;
            for (const Link& l : chain_) {
                if (l.wd != e->wd || l.name != e->name) continue;
                // The last event of a batch tells the state: a write after a removal is a new file.
                if (e->mask & (IN_CLOSE_WRITE | IN_MOVED_TO))
                    change = Change::Written;
                else if (e->mask & (IN_DELETE | IN_MOVED_FROM))
                    change = Change::Removed;
                else if ((e->mask & IN_CREATE) && is_link(fs::path(l.folder) / l.name))
                    change = Change::Written;
                break;
            }
        }
    }
    if (change == Change::None) return change;
    // Something along the chain changed: follow it again, and a link that now leads nowhere is a removal.
    if (chain_.size() > 1 || is_link(path_)) {
        (void)rewatch();  // a folder that vanished is reported by the removal; the next change retries
        std::error_code ec;
        if (change == Change::Written && !fs::exists(path_, ec)) change = Change::Removed;
    }
    return change;
}

}  // namespace puddle::params
