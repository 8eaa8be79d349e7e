#include "remote/writable_patterns.hpp"

#include <array>

namespace puddle::remote {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool matches(std::string_view pattern, std::string_view name) {
    if (pattern == "*") return true;
    if (pattern.ends_with(".*")) return name.starts_with(pattern.substr(0, pattern.size() - 1));
    return pattern == name;
}

}  // namespace

WritablePatterns::WritablePatterns(std::string_view text) {
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trim(text.substr(0, comma));
        if (!item.empty()) patterns_.emplace_back(item);
        if (comma == std::string_view::npos) break;
        text.remove_prefix(comma + 1);
    }
}

bool WritablePatterns::device_setting(std::string_view name) {
    constexpr std::array<std::string_view, 4> never{"remote.", "display.", "environment.camera_", "wall."};
    for (std::string_view prefix : never)
        if (name.starts_with(prefix)) return true;
    return false;
}

bool WritablePatterns::allows(const params::ParamDecl& d) const {
    if (device_setting(d.name)) return false;
    for (const std::string& p : patterns_)
        if (matches(p, d.name)) return true;
    return false;
}

}  // namespace puddle::remote
