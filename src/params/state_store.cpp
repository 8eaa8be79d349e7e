#include "params/state_store.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "params/toml_limits.hpp"

namespace puddle::params {

namespace fs = std::filesystem;

std::string StateStore::default_path() {
    if (const char* d = std::getenv("STATE_DIRECTORY"); d && *d) {
        std::string dir = d;
        if (auto colon = dir.find(':'); colon != std::string::npos) dir.resize(colon);  // several: the first
        return (fs::path(dir) / "state.toml").string();
    }
    if (const char* x = std::getenv("XDG_STATE_HOME"); x && *x)
        return (fs::path(x) / "puddle" / "state.toml").string();
    if (const char* h = std::getenv("HOME"); h && *h)
        return (fs::path(h) / ".local" / "state" / "puddle" / "state.toml").string();
    return "puddle-state.toml";
}

namespace {

// "config: PATH:3: ..." from the parser, as the state's own line.
std::string as_state_problem(std::string message) {
    if (message.starts_with("config: ")) message.replace(0, 8, "state: ");
    return message + "; dropped that value, kept the others";
}

constexpr std::string_view aside_infix = ".bad-";

// The sequence number of a set-aside copy's name (PATH.bad-0007-...), or -1 for other files.
long aside_sequence(const std::string& name, const std::string& base) {
    const std::string prefix = base + std::string(aside_infix);
    if (!name.starts_with(prefix)) return -1;
    long seq = 0;
    std::size_t i = prefix.size();
    for (; i < name.size() && name[i] >= '0' && name[i] <= '9' && seq < 100000000; ++i)
        seq = seq * 10 + (name[i] - '0');
    return i > prefix.size() && i < name.size() && name[i] == '-' ? seq : -1;
}

std::string utc_timestamp() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%dT%H%M%SZ", &utc);
    return text;
}

// Writes all of `text`; false with errno set on failure.
bool write_all(int fd, std::string_view text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Copies `from` to `to`, which must not exist yet (O_EXCL): for file systems without hard links.
bool copy_new_file(const std::string& from, const std::string& to, int& err) {
    const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return err = errno, false;
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (out < 0) {
        err = errno;
        ::close(in);
        return false;
    }
    char buffer[65536];
    bool ok = true;
    for (;;) {
        const ssize_t n = ::read(in, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) break;
        if (n < 0 || !write_all(out, std::string_view(buffer, static_cast<std::size_t>(n)))) {
            ok = false;
            break;
        }
    }
    ok = ok && ::fsync(out) == 0;
    if (!ok) err = errno;
    ::close(in);
    ::close(out);
    if (!ok) ::unlink(to.c_str());
    return ok;
}

void sync_folder(const fs::path& folder) {
    if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

fs::path folder_of(const std::string& path) {
    const fs::path p(path);
    return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

}  // namespace

StateStore::Loaded StateStore::load() const {
    Loaded out;
    std::error_code ec;
    if (!fs::exists(path_, ec)) return out;
    auto text = read_toml_file(path_);
    auto parsed = text ? parse_config_keeping_valid(*text, path_) : Result<PartialConfig>(text.error());
    if (!parsed) {
        out.problems.push_back(fmt::format("state: {} is unreadable ({}); started from the config", path_,
                                           parsed.error().message));
        return out;
    }
    for (std::string& p : parsed->dropped) out.problems.push_back(as_state_problem(std::move(p)));
    if (!parsed->config.knobs.empty()) {
        out.problems.push_back(
            fmt::format("state: {}: holds [[knob]] tables, which belong in the config; dropped them", path_));
        parsed->config.knobs.clear();
    }
    out.state = std::move(parsed->config);
    return out;
}

Result<std::string> StateStore::set_aside() const {
    const fs::path folder = folder_of(path_);
    const std::string base = fs::path(path_).filename().string();
    std::vector<std::pair<long, fs::path>> copies;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (const long seq = aside_sequence(e.path().filename().string(), base); seq >= 0)
            copies.emplace_back(seq, e.path());
    std::sort(copies.begin(), copies.end());
    long seq = copies.empty() ? 1 : copies.back().first + 1;
    const std::string stamp = utc_timestamp();
    std::string aside;
    for (int attempt = 0;; ++attempt, ++seq) {
        aside = (folder / fmt::format("{}{}{:04}-{}", base, aside_infix, seq, stamp)).string();
        // A hard link keeps the original bytes under the new name at no cost: save() later renames a new
        // file over the state's name, and the link still holds the old one. link() never overwrites.
        if (::link(path_.c_str(), aside.c_str()) == 0) break;
        int err = errno;
        if (err != EEXIST && copy_new_file(path_, aside, err)) break;
        if (err != EEXIST || attempt >= 100)
            return make_error(ExitCode::Runtime, "state: cannot keep a copy of {} as {}: {}", path_, aside,
                              std::strerror(err));
    }
    copies.emplace_back(seq, aside);
    for (std::size_t i = 0; i + kept_copies < copies.size(); ++i) fs::remove(copies[i].second, ec);
    sync_folder(folder);
    return aside;
}

Result<std::string> StateStore::write_temporary(std::string_view text) const {
    const fs::path target(path_);
    std::error_code ec;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    const std::string temp = path_ + ".tmp";
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        return make_error(ExitCode::Runtime, "state: cannot write {}: {}", temp, std::strerror(errno));
    if (!write_all(fd, text)) {
        const int err = errno;
        ::close(fd);
        return make_error(ExitCode::Runtime, "state: cannot write {}: {}", temp, std::strerror(err));
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
    sync_folder(folder_of(path_));  // the rename is durable only once the folder is flushed too
    return {};
}

}  // namespace puddle::params
