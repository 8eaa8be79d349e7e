#pragma once
// Watches the config file for edits with inotify(7). It watches folders, not the file: editors save by
// writing a new file and renaming it over the old one, which would end a watch on the file itself.
// A config that is a symbolic link (/etc/puddle/puddle.toml -> /opt/signage/puddle.toml, as config
// management and read-only images ship it) is followed: the folder of the link and of every target
// along the chain is watched, so editing the target, re-pointing a link (`ln -sfn`) or replacing a
// folder's entry all count, and the chain is resolved again after each change.
// Polled from the frame loop; never blocks, and allocates only when something changed.

#include <string>
#include <vector>

#include "util/result.hpp"

namespace puddle::params {

class ConfigWatcher {
public:
    enum class Change { None, Written, Removed };

    // Errors: the folder of the config (or of a link's target) cannot be watched (missing, no
    // permission, inotify limits), named in the message.
    static Result<ConfigWatcher> watch(const std::string& path);
    ConfigWatcher(ConfigWatcher&& other) noexcept;
    ConfigWatcher& operator=(ConfigWatcher&& other) noexcept;
    ConfigWatcher(const ConfigWatcher&) = delete;
    ConfigWatcher& operator=(const ConfigWatcher&) = delete;
    ~ConfigWatcher();

    // What happened to the file since the last poll: Written once a new version is complete (closed
    // after writing, renamed into place, or a link along the way re-pointed to an existing file),
    // Removed when it is gone or a link now points nowhere (and nothing replaced it yet).
    Change poll();
    int fd() const { return fd_; }

    // One entry along the chain: a folder's watch and the name in it that leads to the config.
    struct Link {
        int wd = -1;
        std::string folder;
        std::string name;
    };
    // The chain being watched, from the path given to the final file (for logs and tests).
    const std::vector<Link>& chain() const { return chain_; }

private:
    ConfigWatcher(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
    Result<void> rewatch();
    int fd_ = -1;
    std::string path_;  // as given (absolute): the start of the chain
    std::vector<Link> chain_;
};

}  // namespace puddle::params
