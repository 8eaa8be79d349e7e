#include "params/toml_syntax_error.hpp"

#include <fmt/format.h>

#include "params/registry.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// `a."b c".d` -> a.b c.d: the dotted key as the registry spells it.
std::string unquote_key(std::string_view key) {
    std::string out;
    char quote = 0;
    for (char c : key) {
        if (quote) {
            if (c == quote)
                quote = 0;
            else
                out += c;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c != ' ' && c != '\t') {
            out += c;
        }
    }
    return out;
}

// The text before a '#' that is outside quotes.
std::string_view before_comment(std::string_view s) {
    char quote = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (quote) {
            if (s[i] == quote) quote = 0;
        } else if (s[i] == '"' || s[i] == '\'') {
            quote = s[i];
        } else if (s[i] == '#') {
            return s.substr(0, i);
        }
    }
    return s;
}

// The key and the value text of `line`'s assignment; both empty when it is not one.
struct Assignment {
    std::string key;
    std::string_view value;
};

Assignment assignment_at(std::string_view text, int line) {
    std::string table;
    std::string_view at;
    int n = 1;
    for (std::size_t start = 0; start <= text.size() && n <= line; ++n) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view l = trim(before_comment(text.substr(start, end - start)));
        if (n == line)
            at = l;
        else if (l.starts_with('[') && l.ends_with(']'))
            table =
                unquote_key(l.substr(l.starts_with("[[") ? 2 : 1, l.size() - (l.starts_with("[[") ? 4 : 2)));
        start = end + 1;
    }
    const std::size_t eq = at.find('=');
    if (eq == std::string_view::npos || eq == 0) return {};
    const std::string key = unquote_key(at.substr(0, eq));
    if (key.empty()) return {};
    return {table.empty() ? key : table + "." + key, trim(at.substr(eq + 1))};
}

bool is_number(const ParamDecl& d) {
    return d.kind == ParamKind::Int || d.kind == ParamKind::Float || d.kind == ParamKind::Vec3 ||
           d.kind == ParamKind::Color;
}

}  // namespace

std::string key_at_line(std::string_view text, int line) {
    return assignment_at(text, line).key;
}

std::string explain_toml_error(std::string_view text, int line, std::string_view description) {
    const Assignment a = assignment_at(text, line);
    if (a.key.empty()) return safe_quote(description, 200);
    // toml++ 3.3's words for a number that does not fit: "is not representable in 64 bits" (integers),
    // "could not be interpreted as a value" (a double overflowing to infinity).
    const bool too_big = description.find("not representable") != std::string_view::npos ||
                         description.find("could not be interpreted") != std::string_view::npos;
    if (const ParamDecl* d = find_param(a.key); d && is_number(*d) && too_big)
        return out_of_range(*d, safe_quote(a.value)).message;
    return fmt::format("{}: {}", safe_quote(a.key), safe_quote(description, 200));
}

}  // namespace puddle::params
