#pragma once
// Watches the config file for edits with inotify(7). It watches folders, not the file: editors save by
// writing a new file and renaming it over the old one, which would end a watch on the file itself.
// The path is walked one name at a time, as the kernel resolves it, and the folder holding every name
// along the way is watched for that name: the folders leading to the config, every symbolic link met
// (the config itself, /etc/puddle/puddle.toml -> /opt/signage/puddle.toml, or a folder such as
// /opt/signage/current -> v1) and every folder along each link's target. So editing the target,
// re-pointing a link (`ln -sfn`, or a rename over it), replacing a folder's entry, removing a folder and
// making it again, or swapping a folder by renames all count, and the path is walked again after each
// change. Where a folder is missing, its nearest existing ancestor is watched for it to come back.
// One watch per folder (a few dozen at most: one per name along the path and its links), never one per
// file. Polled from the frame loop; never blocks, and allocates only when something changed.

#include <string>
#include <vector>

#include "util/result.hpp"
#include "util/unique_fd.hpp"

namespace puddle::params {

class ConfigWatcher {
public:
    enum class Change { None, Written, Removed };

    // Errors: inotify cannot be set up (limits), the folder of the config (or of a link's target) is
    // missing or cannot be watched (no permission, inotify limits), or more than 40 links in a row
    // (the kernel's ELOOP limit); the path is named in the message. Folders above it that cannot be
    // watched (no read permission) are skipped: only their renames go unseen.
    static Result<ConfigWatcher> watch(const std::string& path);
    // What happened to the config since the last poll:
    // Written once a new version is complete (closed after writing, renamed into place, a link or a
    // folder along the way changed and the path leads to something again), or something that is not a
    // file took its place (a folder, a FIFO: the reload that follows says what it is);
    // Removed once when the path stops leading anywhere (the file, a folder or a link's target is gone),
    // and not again until something is back.
    Change poll();
    int fd() const { return fd_.get(); }

    // One name along the way, and the watch on the folder that holds it.
    struct Step {
        enum class Kind { Folder, Link, File };
        int wd = -1;  // -1: the folder could not be watched
        std::string folder;
        std::string name;
        Kind kind = Kind::Folder;  // Folder: a folder on the way, or the first missing name
    };
    // The links met and the final name, from the path given to the file (for logs and tests).
    std::vector<Step> chain() const;
    // Every name along the way, folders included, in the order walked.
    const std::vector<Step>& steps() const { return steps_; }

private:
    ConfigWatcher(UniqueFd fd, std::string path) : fd_(std::move(fd)), path_(std::move(path)) {}
    Result<void> rewatch();
    UniqueFd fd_;       // the inotify instance
    std::string path_;  // as given, made absolute: where each walk starts
    std::vector<Step> steps_;
    bool present_ = false;  // the walk reached an existing final name
};

}  // namespace puddle::params
