#include "params/config_watcher.hpp"

#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace puddle::params {

namespace fs = std::filesystem;
using Step = ConfigWatcher::Step;

namespace {

// Creation counts for anything but a regular file (a link, a folder coming back, a FIFO in the file's
// place): a new regular file is complete when it is closed or renamed in. IN_DONT_FOLLOW and IN_ONLYDIR:
// the walk hands over real folders; one swapped for a link meanwhile is left to the event that swapped it.
constexpr std::uint32_t watch_mask =
    IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM | IN_CREATE | IN_ONLYDIR | IN_DONT_FOLLOW;
constexpr int max_links = 40;  // as the kernel's ELOOP limit for path resolution

struct Walk {
    std::vector<Step> steps;
    bool present = false;  // the path leads to something (a file, or whatever took its place)
    int error = 0;         // why a folder along the way could not be entered (errno), when present is false
    bool too_many_links = false;
};

// Pushes the names of `p` so that the first comes out first; "." and empty names (a trailing slash) are
// nothing to resolve.
void push_names(std::vector<std::string>& pending, const fs::path& p) {
    const std::size_t at = pending.size();
    for (const fs::path& name : p.relative_path())
        if (!name.empty() && name != ".") pending.push_back(name.string());
    std::reverse(pending.begin() + static_cast<std::ptrdiff_t>(at), pending.end());
}

// Resolves `start` (absolute) one name at a time, as the kernel does (path_resolution(7)): a link's target
// continues the walk from the link's folder (or from / when absolute) and ".." goes to the real parent.
// Every name met is a step; the walk stops at the first name that is missing or is not a folder.
Walk walk(const fs::path& start) {
    Walk w;
    std::vector<std::string> pending;  // names still to resolve, the next one last
    push_names(pending, start);
    fs::path folder = "/";
    int links = 0;
    while (!pending.empty()) {
        std::string name = std::move(pending.back());
        pending.pop_back();
        if (name == "..") {
            folder = folder.parent_path();
            continue;
        }
        const bool last = pending.empty();
        const fs::path entry = folder / name;
        struct stat st {};
        if (::lstat(entry.c_str(), &st) != 0) {
            w.error = errno;
            w.steps.push_back(
                {-1, folder.string(), std::move(name), last ? Step::Kind::File : Step::Kind::Folder});
            return w;
        }
        if (S_ISLNK(st.st_mode)) {
            w.steps.push_back({-1, folder.string(), std::move(name), Step::Kind::Link});
            if (++links > max_links) {
                w.too_many_links = true;
                return w;
            }
            std::error_code ec;
            const fs::path target = fs::read_symlink(entry, ec);
            if (ec) {  // replaced between the two looks: the event that did it walks again
                w.error = ec.value();
                return w;
            }
            if (target.is_absolute()) folder = "/";
            push_names(pending, target);
            continue;
        }
        if (last) {
            w.steps.push_back({-1, folder.string(), std::move(name), Step::Kind::File});
            w.present = true;
            return w;
        }
        w.steps.push_back({-1, folder.string(), std::move(name), Step::Kind::Folder});
        if (!S_ISDIR(st.st_mode)) {
            w.error = ENOTDIR;
            return w;
        }
        folder = entry;
    }
    w.present = true;  // the path (or its last link) names a folder: the reload will say so
    return w;
}

}  // namespace

Result<ConfigWatcher> ConfigWatcher::watch(const std::string& path) {
    UniqueFd fd(inotify_init1(IN_NONBLOCK | IN_CLOEXEC));
    if (!fd)
        return make_error(ExitCode::Runtime, "config: cannot watch {}: inotify: {}", path,
                          std::strerror(errno));
    ConfigWatcher w(std::move(fd), fs::absolute(path).string());
    if (auto r = w.rewatch(); !r) return r.error();
    return w;
}

// Walks the path again and watches the folder of each step. Watches on one folder share a descriptor;
// the ones no step needs any more are dropped, which keeps the kernel's count bounded.
Result<void> ConfigWatcher::rewatch() {
    Walk w = walk(path_);
    int watch_error = 0;  // why the last folder that could not be watched could not be
    for (std::size_t i = 0; i < w.steps.size(); ++i) {
        Step& s = w.steps[i];
        const auto end = w.steps.begin() + static_cast<std::ptrdiff_t>(i);
        const auto same =
            std::find_if(w.steps.begin(), end, [&](const Step& o) { return o.folder == s.folder; });
        if (same != end) {
            s.wd = same->wd;
            continue;
        }
        s.wd = inotify_add_watch(fd_.get(), s.folder.c_str(), watch_mask);
        if (s.wd < 0) watch_error = errno;
    }
    for (const Step& old : steps_) {
        const bool kept =
            std::any_of(w.steps.begin(), w.steps.end(), [&](const Step& s) { return s.wd == old.wd; });
        if (old.wd >= 0 && !kept)
            inotify_rm_watch(fd_.get(), old.wd);  // a shared descriptor fails the second time: fine
    }
    steps_ = std::move(w.steps);
    present_ = w.present;
    if (w.too_many_links)
        return make_error(ExitCode::Runtime, "config: {}: more than {} symbolic links in a row", path_,
                          max_links);
    if (steps_.empty()) return {};
    const Step& end = steps_.back();
    if (!w.present && end.kind != Step::Kind::File)  // a folder on the way is missing (or no folder)
        return make_error(ExitCode::Runtime, "config: cannot watch folder {}: {}",
                          (fs::path(end.folder) / end.name).string(), std::strerror(w.error));
    if (end.wd < 0)
        return make_error(ExitCode::Runtime, "config: cannot watch folder {}: {}", end.folder,
                          std::strerror(watch_error));
    return {};
}

std::vector<Step> ConfigWatcher::chain() const {
    std::vector<Step> out;
    for (const Step& s : steps_)
        if (s.kind != Step::Kind::Folder) out.push_back(s);
    return out;
}

ConfigWatcher::Change ConfigWatcher::poll() {
    bool touched = false;   // an event named a step
    bool complete = false;  // something was closed after writing or renamed into a step's place
    bool replaced = false;  // something that is no regular file appeared at a step (link, folder, FIFO)
    alignas(inotify_event) char buffer[4096];
    for (;;) {
        const ssize_t n = read(fd_.get(), buffer, sizeof buffer);
        if (n <= 0) break;  // EAGAIN: nothing more now
        for (ssize_t at = 0; at < n;) {
            const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
            if (e->mask & IN_Q_OVERFLOW) {  // events were lost: anything may have changed
                touched = replaced = true;
                continue;
            }
            if (e->len == 0) continue;
            for (const Step& s : steps_) {
                if (s.wd != e->wd || s.name != e->name) continue;
                touched = true;
                if (e->mask & (IN_CLOSE_WRITE | IN_MOVED_TO)) {
                    complete = true;
                } else if (e->mask & IN_CREATE) {
                    std::error_code ec;
                    const auto type = fs::symlink_status(fs::path(s.folder) / s.name, ec).type();
                    if (type != fs::file_type::not_found && type != fs::file_type::regular) replaced = true;
                }
                break;
            }
        }
    }
    if (!touched) return Change::None;
    // Something along the way changed: walk again (a folder that is still missing is watched for in its
    // nearest existing ancestor; one that cannot be watched is retried at the next change).
    const bool was_present = present_;
    (void)rewatch();
    if (present_ && (complete || replaced)) return Change::Written;
    if (!present_ && was_present) return Change::Removed;
    return Change::None;
}

}  // namespace puddle::params
