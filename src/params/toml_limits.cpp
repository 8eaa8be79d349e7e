#include "params/toml_limits.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>

#include "util/unique_fd.hpp"

namespace puddle::params {

namespace {

bool is_bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// A tolerant walk over TOML text that follows only what can nest: table headers, dotted keys, arrays and
// inline tables, skipping strings and comments. Where the text is not valid TOML it resynchronises at the
// next line and leaves the complaint to toml++. Iterative over key segments; it recurses only into arrays
// and inline tables, never deeper than the limit.
class NestingScan {
public:
    NestingScan(std::string_view text, std::string_view path) : s_(text), path_(path) {}

    int error_line() const { return error_line_; }
    Result<void> run() {
        while (!error_) {
            skip_blank_lines_and_comments();
            if (at_end()) break;
            if (peek() == '[') {
                advance();
                const bool array = peek() == '[';  // [[knob]]: the array, then its table
                if (array) advance();
                const Key k = scan_key();
                if (!check_key(k, k.segments + (array ? 1 : 0), "table header")) break;
                header_depth_ = k.segments + (array ? 1 : 0);
            } else {
                const Key k = scan_key();
                if (!check_key(k, header_depth_ + k.segments, "key")) break;
                skip_blank();
                if (k.segments > 0 && peek() == '=') {
                    advance();
                    scan_value(header_depth_ + k.segments);
                }
            }
            skip_rest_of_line();
        }
        if (error_) return *error_;
        return {};
    }

private:
    struct Key {
        int segments = 0;
        std::size_t bytes = 0;
        int line = 0;
    };

    bool at_end() const { return i_ >= s_.size(); }
    char peek(std::size_t ahead = 0) const { return i_ + ahead < s_.size() ? s_[i_ + ahead] : '\0'; }
    void advance() {
        if (s_[i_] == '\n') ++line_;
        ++i_;
    }
    void skip_blank() {
        while (!at_end() && (peek() == ' ' || peek() == '\t')) advance();
    }
    void skip_comment() {
        if (peek() == '#')
            while (!at_end() && peek() != '\n') advance();
    }
    void skip_blank_lines_and_comments() {
        for (;;) {
            skip_blank();
            skip_comment();
            if (peek() == '\n' || peek() == '\r')
                advance();
            else
                break;
        }
    }
    // Skips to the next line, stepping over strings: a multi-line string's lines are not statements.
    void skip_rest_of_line() {
        while (!at_end() && peek() != '\n') {
            if (peek() == '"' || peek() == '\'')
                skip_string();
            else if (peek() == '#')
                skip_comment();
            else
                advance();
        }
    }
    // At an opening quote: a basic ("), literal ('), or multi-line (""" or ''') string.
    void skip_string() {
        const char q = peek();
        const bool basic = q == '"';
        if (peek(1) == q && peek(2) == q) {
            for (int k = 0; k < 3; ++k) advance();
            while (!at_end() && !(peek() == q && peek(1) == q && peek(2) == q)) {
                if (basic && peek() == '\\' && i_ + 1 < s_.size()) advance();
                advance();
            }
            for (int k = 0; k < 3 && !at_end(); ++k) advance();
            return;
        }
        advance();
        while (!at_end() && peek() != q && peek() != '\n') {
            if (basic && peek() == '\\' && peek(1) != '\n' && i_ + 1 < s_.size()) advance();
            advance();
        }
        if (peek() == q) advance();
    }
    // A key as written: bare or quoted segments joined by dots. Counted, never recursed into.
    Key scan_key() {
        Key k{0, 0, line_};
        skip_blank();
        const std::size_t start = i_;
        for (;;) {
            skip_blank();
            if (peek() == '"' || peek() == '\'') {
                skip_string();
            } else if (is_bare_key_char(peek())) {
                while (is_bare_key_char(peek())) advance();
            } else {
                break;
            }
            ++k.segments;
            k.bytes = i_ - start;
            skip_blank();
            if (peek() != '.') break;
            advance();
        }
        return k;
    }
    bool check_key(const Key& k, int depth, std::string_view what) {
        if (depth > toml_limits.max_depth)
            error_ = make_error(ExitCode::Config, "config: {}:{}: {} nests {} levels; the limit is {}", path_,
                                k.line, what, depth, toml_limits.max_depth);
        else if (k.bytes > toml_limits.max_key_bytes)
            error_ = make_error(ExitCode::Config, "config: {}:{}: {} is {} bytes long; the limit is {}",
                                path_, k.line, what, k.bytes, toml_limits.max_key_bytes);
        if (error_) error_line_ = k.line;
        return !error_;
    }
    bool enter(int depth) {
        if (depth > toml_limits.max_depth)
            error_ =
                make_error(ExitCode::Config,
                           "config: {}:{}: value nests more than {} levels (arrays or inline tables); the "
                           "limit is {}",
                           path_, line_, toml_limits.max_depth, toml_limits.max_depth);
        if (error_) error_line_ = line_;
        return !error_;
    }
    // A value whose key sits `depth` levels deep; array elements sit one level deeper.
    void scan_value(int depth) {
        skip_blank();
        const char c = peek();
        if (c == '"' || c == '\'') {
            skip_string();
        } else if (c == '[') {
            if (!enter(depth + 1)) return;
            advance();
            for (;;) {
                skip_blank_lines_and_comments();
                if (at_end() || error_) return;
                if (peek() == ']') return advance();
                const std::size_t before = i_;
                scan_value(depth + 1);
                skip_blank_lines_and_comments();
                if (peek() == ',')
                    advance();
                else if (peek() == ']')
                    return advance();
                else if (i_ == before)
                    return;  // not TOML: toml++ will say so
            }
        } else if (c == '{') {
            advance();
            for (;;) {
                skip_blank();
                if (at_end() || error_) return;
                if (peek() == '}') return advance();
                const Key k = scan_key();
                if (!check_key(k, depth + k.segments, "key")) return;
                skip_blank();
                if (k.segments == 0 || peek() != '=') return;
                advance();
                scan_value(depth + k.segments);
                skip_blank();
                if (peek() == ',')
                    advance();
                else if (peek() == '}')
                    return advance();
                else
                    return;
            }
        } else {
            while (!at_end()) {
                const char d = peek();
                if (d == ' ' || d == '\t' || d == '\r' || d == '\n' || d == ',' || d == ']' || d == '}' ||
                    d == '#')
                    break;
                advance();
            }
        }
    }

    std::string_view s_;
    std::string_view path_;
    std::size_t i_ = 0;
    int line_ = 1;
    int header_depth_ = 0;
    std::optional<Error> error_;
    int error_line_ = 0;  // the line error_ names
};

}  // namespace

Result<void> check_toml_limits(std::string_view text, std::string_view path, int* failed_line) {
    if (text.size() > toml_limits.max_bytes)
        return make_error(ExitCode::Config, "config: {}: {} bytes; the limit is {} bytes (1 MiB)", path,
                          text.size(), toml_limits.max_bytes);
    // Nesting first: a 50 000-level key is also a long line, and its depth is what to fix.
    NestingScan scan(text, path);
    if (auto r = scan.run(); !r) {
        if (failed_line) *failed_line = scan.error_line();
        return r;
    }
    int line = 1;
    for (std::size_t start = 0; start < text.size(); ++line) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        if (end - start > toml_limits.max_line_bytes) {
            if (failed_line) *failed_line = line;
            return make_error(ExitCode::Config, "config: {}:{}: line is {} bytes long; the limit is {}", path,
                              line, end - start, toml_limits.max_line_bytes);
        }
        start = end + 1;
    }
    return {};
}

std::string_view file_kind(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

Result<std::string> read_toml_file(const std::string& path) {
    // O_NONBLOCK: opening a FIFO for reading would wait for a writer, with the frame loop (and SIGTERM's
    // handling) stuck in open(); only a regular file is read at all.
    const UniqueFd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (!fd) return make_error(ExitCode::Config, "config: {}: cannot open: {}", path, std::strerror(errno));
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode)) {
        const int err = errno;
        const mode_t mode = st.st_mode;
        if (mode == 0)
            return make_error(ExitCode::Config, "config: {}: cannot read: {}", path, std::strerror(err));
        return make_error(ExitCode::Config, "config: {}: is {}, not a file", path, file_kind(mode));
    }
    std::string text(toml_limits.max_bytes + 1, '\0');
    std::size_t got = 0;
    while (got < text.size()) {
        const ssize_t n = ::read(fd.get(), text.data() + got, text.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0)
            return make_error(ExitCode::Config, "config: {}: cannot read: {}", path, std::strerror(errno));
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    text.resize(got);
    if (text.size() > toml_limits.max_bytes)
        return make_error(ExitCode::Config, "config: {}: larger than 1 MiB; the limit is {} bytes", path,
                          toml_limits.max_bytes);
    return text;
}

}  // namespace puddle::params
