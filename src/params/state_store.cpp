#include "params/state_store.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace puddle::params {

namespace fs = std::filesystem;

std::string StateStore::default_path() {
    if (const char* d = std::getenv("STATE_DIRECTORY"); d && *d) {
        std::string dir = d;
        if (auto colon = dir.find(':'); colon != std::string::npos) dir.resize(colon);  // several: the first
        return (fs::path(dir) / "state.toml").string();
    }
    if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x) return (fs::path(x) / "puddle" / "state.toml").string();
    if (const char* h = std::getenv("HOME"); h && *h)
        return (fs::path(h) / ".local" / "state" / "puddle" / "state.toml").string();
    return "puddle-state.toml";
}

StateStore::Loaded StateStore::load() const {
    Loaded out;
    std::error_code ec;
    if (!fs::exists(path_, ec)) return out;
    auto state = load_config_file(path_);
    if (state && state->knobs.empty()) {
        out.state = std::move(*state);
        return out;
    }
    const std::string reason = state ? "it holds [[knob]] tables" : state.error().message;
    const std::string aside = path_ + ".corrupt";
    fs::rename(path_, aside, ec);
    out.warning = fmt::format("state: {} is unreadable ({}); moved it to {} and started from the config",
                              path_, reason, ec ? std::string("(could not move: ") + ec.message() + ")" : aside);
    return out;
}

Result<std::string> StateStore::write_temporary(std::string_view text) const {
    const fs::path target(path_);
    std::error_code ec;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    const std::string temp = path_ + ".tmp";
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return make_error(ExitCode::Runtime, "state: cannot write {}: {}", temp, std::strerror(errno));
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int err = errno;
            ::close(fd);
            return make_error(ExitCode::Runtime, "state: cannot write {}: {}", temp, std::strerror(err));
        }
        done += static_cast<std::size_t>(n);
    }
    const bool synced = ::fsync(fd) == 0;
    const int err = errno;
    ::close(fd);
    if (!synced) return make_error(ExitCode::Runtime, "state: cannot flush {}: {}", temp, std::strerror(err));
    return temp;
}

Result<void> StateStore::save(std::string_view text) const {
    auto temp = write_temporary(text);
    if (!temp) return temp.error();
    if (::rename(temp->c_str(), path_.c_str()) != 0)
        return make_error(ExitCode::Runtime, "state: cannot replace {}: {}", path_, std::strerror(errno));
    // The rename is durable only once the folder is flushed too.
    const fs::path parent = fs::path(path_).has_parent_path() ? fs::path(path_).parent_path() : fs::path(".");
    if (const int dir = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

}  // namespace puddle::params
