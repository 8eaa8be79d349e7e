#pragma once
// Watches the config file for edits with inotify. It watches the folder, not the file: editors save by
// writing a new file and renaming it over the old one, which would end a watch on the file itself.
// Polled from the frame loop; never blocks.

#include <string>

#include "util/result.hpp"

namespace puddle::params {

class ConfigWatcher {
public:
    enum class Change { None, Written, Removed };

    static Result<ConfigWatcher> watch(const std::string& path);
    ConfigWatcher(ConfigWatcher&& other) noexcept;
    ConfigWatcher& operator=(ConfigWatcher&& other) noexcept;
    ConfigWatcher(const ConfigWatcher&) = delete;
    ConfigWatcher& operator=(const ConfigWatcher&) = delete;
    ~ConfigWatcher();

    // What happened to the file since the last poll: Written once a new version is complete (closed
    // after writing, or renamed into place), Removed when it is gone (and nothing replaced it yet).
    Change poll();
    int fd() const { return fd_; }

private:
    ConfigWatcher(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}
    int fd_ = -1;
    std::string name_;  // the file's name inside the watched folder
};

}  // namespace puddle::params
