#pragma once
// The knob state on disk: what the knobs changed survives a restart or a power cut. Written atomically
// (a temporary file, fsync, rename, fsync of the folder), so a crash at any moment leaves either the
// old state or the new one, never half a file. A corrupt file is moved aside and never stops the program.

#include <optional>
#include <string>
#include <string_view>

#include "params/config_loader.hpp"
#include "util/result.hpp"

namespace puddle::params {

class StateStore {
public:
    explicit StateStore(std::string path) : path_(std::move(path)) {}
    // $STATE_DIRECTORY (systemd's StateDirectory=), else $XDG_STATE_HOME/puddle, else
    // ~/.local/state/puddle; the file is state.toml.
    static std::string default_path();

    struct Loaded {
        std::optional<Config> state;  // none when there is no file (or it was corrupt)
        std::string warning;          // set when a corrupt file was moved aside
    };
    Loaded load() const;
    Result<void> save(std::string_view text) const;
    // The first half of save(): the complete temporary file, not yet renamed into place. Separate so a
    // test can stop there, as a crash would.
    Result<std::string> write_temporary(std::string_view text) const;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace puddle::params
