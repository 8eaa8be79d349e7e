#pragma once
// The knob state on disk: what the knobs changed survives a restart or a power cut. Written atomically
// (a temporary file, fsync, rename, fsync of the folder), so a crash at any moment leaves either the
// old state or the new one, never half a file (test StateStore.SigkillDuringSavesLeavesTheOldOrTheNewState).
// The saved state is the user's data: a bad key is dropped and reported, every valid key is kept, and the
// original file is set aside under a new name before anything rewrites it; a file that could not be set
// aside is never replaced. A state path that is a symbolic link (or a chain of them) is written through:
// the file it leads to is replaced and the link stays a link (a read-only image whose state.toml points at
// persistent storage).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "params/config_loader.hpp"
#include "util/result.hpp"

namespace puddle::params {

class StateStore {
public:
    // Set-aside copies kept beside the state file; the oldest beyond this are deleted.
    static constexpr int kept_copies = 5;
    // Symbolic links followed in a row before giving up, as the kernel's ELOOP limit.
    static constexpr int max_links = 40;

    explicit StateStore(std::string path) : path_(std::move(path)) {}
    // $STATE_DIRECTORY (systemd's StateDirectory=), else $XDG_STATE_HOME/puddle, else
    // ~/.local/state/puddle; the file is state.toml.
    static std::string default_path();

    struct Loaded {
        std::optional<Config> state;        // the valid keys; none when there is no file or none can be read
        std::vector<std::string> problems;  // one line per dropped key, or the reason nothing could be read
    };
    // Reads the file (through links) and changes nothing on disk, so read-only commands (--print-config)
    // can use it.
    Loaded load() const;
    // Keeps the file as it is now under a new name beside the file the path leads to (TARGET below: the
    // path itself, or the end of its links), TARGET.bad-SEQ-YYYYMMDDTHHMMSSZ (SEQ counts up, so the order
    // survives a clock that jumps back on a board without a real-time clock), never overwriting an earlier
    // copy, and deletes the oldest copies beyond kept_copies. Tries a hard link (the original stays in
    // place until save() renames over it), then a copy, then renaming the file, which its folder may allow
    // even when this user can neither read nor link it (a root-owned 0600 file left by `sudo puddle`).
    // Returns the copy's path. Errors: a folder at the path (never moved), or no way worked. After an
    // error save() refuses (refusal()), so the file stays as it is, until the file is moved away or
    // removed (by hand, or by a package upgrade): then saving creates a new file and the refusal ends.
    Result<std::string> set_aside();
    // Writes `text` as TARGET.tmp beside TARGET, fsyncs it, renames it onto TARGET and fsyncs the folder.
    // A missing folder is made for a plain path, not for a link's target (storage that is not mounted:
    // nothing is written beneath it). Errors (one line naming the path and why): refused after a failed
    // set_aside(), a link whose target folder is missing, more than max_links links, cannot write, flush
    // or rename. The temporary file is removed on every error.
    Result<void> save(std::string_view text);
    // The first half of save(): the complete temporary file, not yet renamed into place. Separate so a
    // test can stop there, as a crash would.
    Result<std::string> write_temporary(std::string_view text) const;
    // Why save() refuses (the failed set_aside()'s line), or empty.
    const std::string& refusal() const { return refusal_; }
    const std::string& path() const { return path_; }

private:
    struct Temporary {
        std::string temp, target;
    };
    Result<Temporary> write_beside_target(std::string_view text) const;
    Result<std::string> keep_aside() const;
    bool refused_file_gone() const;  // the path leads to nothing now

    std::string path_;
    std::string refusal_;
};

}  // namespace puddle::params
