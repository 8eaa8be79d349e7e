#pragma once
// The knob state on disk: what the knobs changed survives a restart or a power cut. Written atomically
// (a temporary file, fsync, rename, fsync of the folder), so a crash at any moment leaves either the
// old state or the new one, never half a file (test StateStore.SigkillDuringSavesLeavesTheOldOrTheNewState).
// The saved state is the user's data: a bad key is dropped and reported, every valid key is kept, and the
// original file is set aside under a new name before anything rewrites it.

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

    explicit StateStore(std::string path) : path_(std::move(path)) {}
    // $STATE_DIRECTORY (systemd's StateDirectory=), else $XDG_STATE_HOME/puddle, else
    // ~/.local/state/puddle; the file is state.toml.
    static std::string default_path();

    struct Loaded {
        std::optional<Config> state;        // the valid keys; none when there is no file or none can be read
        std::vector<std::string> problems;  // one line per dropped key, or the reason nothing could be read
    };
    // Reads the file and changes nothing on disk, so read-only commands (--print-config) can use it.
    Loaded load() const;
    // Keeps the file as it is now under a new name, PATH.bad-SEQ-YYYYMMDDTHHMMSSZ (SEQ counts up, so the
    // order survives a clock that jumps back on a board without a real-time clock), never overwriting an
    // earlier copy, and deletes the oldest copies beyond kept_copies. Returns the copy's path.
    Result<std::string> set_aside() const;
    Result<void> save(std::string_view text) const;
    // The first half of save(): the complete temporary file, not yet renamed into place. Separate so a
    // test can stop there, as a crash would.
    Result<std::string> write_temporary(std::string_view text) const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace puddle::params
