#include "params/state_store.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>

#include "params/toml_limits.hpp"
#include "util/unique_fd.hpp"

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

// "config: PATH:3: ..." from the parser, as the state's own words.
std::string as_state_line(std::string message) {
    if (message.starts_with("config: ")) message.replace(0, 8, "state: ");
    return message;
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
        if (n == 0) errno = EIO;  // no progress and no error: give up rather than spin
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Copies the regular file `from` to `to`, which must not exist yet (O_EXCL); 0 or errno. Anything else
// (a FIFO: opened without blocking) is not copied.
int copy_new_file(const char* from, const char* to) {
    UniqueFd in(::open(from, O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (!in) return errno;
    struct stat st {};
    if (::fstat(in.get(), &st) != 0 || !S_ISREG(st.st_mode)) return EINVAL;
    UniqueFd out(::open(to, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
    if (!out) return errno;
    char buffer[65536];
    int err = 0;
    for (;;) {
        const ssize_t n = ::read(in.get(), buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n == 0) break;
        if (n < 0 || !write_all(out.get(), std::string_view(buffer, static_cast<std::size_t>(n)))) {
            err = errno;
            break;
        }
    }
    if (err == 0 && ::fsync(out.get()) != 0) err = errno;
    in.reset();
    out.reset();
    if (err != 0) ::unlink(to);
    return err;
}

// Renames `from` to `to` unless `to` exists; 0 or errno (EEXIST when it does).
int rename_new_name(const char* from, const char* to) {
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_NOREPLACE) == 0) return 0;
    if (errno != EINVAL) return errno;
    // A file system without RENAME_NOREPLACE (some network ones): look, then rename.
    if (::access(to, F_OK) == 0) return EEXIST;
    return ::rename(from, to) == 0 ? 0 : errno;
}

// Keeps `from` (any kind of file but a folder) under the new name `to`: a hard link (free, and the
// original stays in place), else a copy (file systems without hard links), else a rename, which a
// writable folder allows even for a file this user may neither link nor read. 0, or the errno of the
// last way tried; EEXIST as soon as `to` is taken.
int keep_under_new_name(const char* from, const char* to) {
    if (::link(from, to) == 0) return 0;
    if (errno == EEXIST) return EEXIST;
    if (const int err = copy_new_file(from, to); err == 0 || err == EEXIST) return err;
    return rename_new_name(from, to);
}

void sync_folder(const fs::path& folder) {
    if (const UniqueFd dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)); dir)
        ::fsync(dir.get());
}

fs::path folder_of(const fs::path& p) {
    return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

// The file `path` leads to: itself, or the end of its chain of symbolic links, each relative target
// taken from its own link's folder as the kernel does. The end need not exist (a dangling link names
// the file a save creates).
Result<fs::path> follow_links(const std::string& path) {
    fs::path p = path;
    for (int hop = 0; hop <= StateStore::max_links; ++hop) {
        struct stat st {};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
        std::error_code ec;
        const fs::path target = fs::read_symlink(p, ec);
        if (ec)
            return make_error(ExitCode::Runtime, "state: cannot read the link {}: {}", p.string(),
                              ec.message());
        p = p.parent_path() / target;  // an absolute target replaces the folder
    }
    return make_error(ExitCode::Runtime, "state: {}: more than {} symbolic links in a row; not saving", path,
                      StateStore::max_links);
}

// Why `folder` cannot hold the state file, or null when it can.
const char* unusable_folder(const fs::path& folder) {
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0) return std::strerror(errno);
    return S_ISDIR(st.st_mode) ? nullptr : "not a folder";
}

// How a message names the state file: the path, and where it leads when that differs.
std::string describe(const std::string& path, const fs::path& target) {
    return target == fs::path(path) ? path : fmt::format("{} (-> {})", path, target.string());
}

}  // namespace

StateStore::Loaded StateStore::load() const {
    Loaded out;
    std::error_code ec;
    if (!fs::exists(path_, ec)) return out;
    auto text = read_toml_file(path_);
    auto parsed = text ? parse_config_keeping_valid(*text, path_) : Result<PartialConfig>(text.error());
    if (!parsed) {
        out.problems.push_back(fmt::format("{}; no saved value could be read (the config's values apply)",
                                           as_state_line(std::move(parsed.error().message))));
        return out;
    }
    for (std::string& p : parsed->dropped)
        out.problems.push_back(as_state_line(std::move(p)) + "; dropped that value, kept the others");
    if (parsed->syntax_error) out.problems.push_back(as_state_line(std::move(*parsed->syntax_error)));
    if (!parsed->config.knobs.empty()) {
        out.problems.push_back(
            fmt::format("state: {}: holds [[knob]] tables, which belong in the config; dropped them", path_));
        parsed->config.knobs.clear();
    }
    out.state = std::move(parsed->config);
    return out;
}

Result<std::string> StateStore::set_aside() {
    auto aside = keep_aside();
    if (!aside) refusal_ = aside.error().message + "; saving resumes once it is moved away";
    return aside;
}

Result<std::string> StateStore::keep_aside() const {
    auto target = follow_links(path_);
    if (!target) return target.error();
    struct stat st {};
    if (::lstat(target->c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        return make_error(ExitCode::Runtime, "state: {} is a folder, not a file; knob changes are not saved",
                          describe(path_, *target));
    const fs::path folder = folder_of(*target);
    const std::string base = target->filename().string();
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
        // None of the ways overwrites an earlier copy: a taken name is EEXIST, and the next number is tried.
        const int err = keep_under_new_name(target->c_str(), aside.c_str());
        if (err == 0) break;
        if (err != EEXIST || attempt >= 100)
            return make_error(ExitCode::Runtime,
                              "state: cannot set {} aside as {}: {}; knob changes are not saved, so it stays "
                              "as it is",
                              describe(path_, *target), aside, std::strerror(err));
    }
    copies.emplace_back(seq, aside);
    for (std::size_t i = 0; i + kept_copies < copies.size(); ++i) fs::remove(copies[i].second, ec);
    sync_folder(folder);
    return aside;
}

Result<StateStore::Temporary> StateStore::write_beside_target(std::string_view text) const {
    if (!refusal_.empty() && !refused_file_gone()) return make_error(ExitCode::Runtime, "{}", refusal_);
    auto target = follow_links(path_);
    if (!target) return target.error();
    const fs::path folder = folder_of(*target);
    if (*target == fs::path(path_)) {
        std::error_code ec;
        fs::create_directories(folder, ec);  // a first start; an error shows when the file is opened
    } else if (const char* why = unusable_folder(folder)) {  // storage not mounted: write nothing beneath
        return make_error(ExitCode::Runtime,
                          "state: {} links to {}, whose folder {} cannot be used ({}); not saving", path_,
                          target->string(), folder.string(), why);
    }
    Temporary t{target->string() + ".tmp", target->string()};
    // O_NOFOLLOW: a link named like the temporary file is not written through.
    UniqueFd fd(::open(t.temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644));
    if (!fd) return make_error(ExitCode::Runtime, "state: cannot write {}: {}", t.temp, std::strerror(errno));
    int err = write_all(fd.get(), text) ? 0 : errno;
    const char* failed = "write";
    if (err == 0 && ::fsync(fd.get()) != 0) err = errno, failed = "flush";
    fd.reset();
    if (err != 0) {
        ::unlink(t.temp.c_str());  // a failed save leaves nothing behind (a full disk: an empty file)
        return make_error(ExitCode::Runtime, "state: cannot {} {}: {}", failed, t.temp, std::strerror(err));
    }
    return t;
}

Result<std::string> StateStore::write_temporary(std::string_view text) const {
    auto t = write_beside_target(text);
    if (!t) return t.error();
    return t->temp;
}

bool StateStore::refused_file_gone() const {
    auto target = follow_links(path_);
    struct stat st {};
    return target && ::lstat(target->c_str(), &st) != 0 && errno == ENOENT;
}

Result<void> StateStore::save(std::string_view text) {
    const bool lifting_refusal = !refusal_.empty();
    auto t = write_beside_target(text);
    if (!t) return t.error();
    // Saving after a refusal only creates the file: should the refused one come back meanwhile, it stays.
    const int renamed = lifting_refusal ? ::renameat2(AT_FDCWD, t->temp.c_str(), AT_FDCWD, t->target.c_str(),
                                                      RENAME_NOREPLACE)
                                        : ::rename(t->temp.c_str(), t->target.c_str());
    if (renamed != 0) {
        const int err = errno;
        ::unlink(t->temp.c_str());
        return make_error(ExitCode::Runtime, "state: cannot replace {}: {}", describe(path_, t->target),
                          std::strerror(err));
    }
    sync_folder(folder_of(t->target));  // the rename is durable only once the folder is flushed too
    refusal_.clear();
    return {};
}

}  // namespace puddle::params
