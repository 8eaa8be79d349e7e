#pragma once
// Text made valid UTF-8 whatever came in (a payload from the broker, a file name, a config value): each
// byte that does not start a well-formed sequence (a stray continuation byte, a truncated or overlong
// sequence, a surrogate, beyond U+10FFFF) becomes U+FFFD, as nlohmann's replace handler does. Journals,
// terminals and JSON all need valid UTF-8; what was valid is kept byte for byte.

#include <cstddef>
#include <string>
#include <string_view>

namespace puddle {

// The length of the well-formed UTF-8 sequence at the start of `s` (1 to 4), 0 when there is none.
inline std::size_t utf8_sequence_length(std::string_view s) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
    const unsigned char c = b(0);
    if (c < 0x80) return 1;
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range (RFC 3629's table)
    if (c >= 0xC2 && c <= 0xDF) {
        n = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;  // overlong
        if (c == 0xED) hi = 0x9F;  // surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;  // overlong
        if (c == 0xF4) hi = 0x8F;  // beyond U+10FFFF
    } else {
        return 0;
    }
    if (s.size() < n || b(1) < lo || b(1) > hi) return 0;
    for (std::size_t i = 2; i < n; ++i)
        if (b(i) < 0x80 || b(i) > 0xBF) return 0;
    return n;
}

// Appends `text` to `out` (any container of char with append(const char*, const char*)), invalid bytes
// as U+FFFD.
template <class Out>
void append_valid_utf8(std::string_view text, Out& out) {
    static constexpr char replacement[] = "\xEF\xBF\xBD";
    std::size_t start = 0, i = 0;  // [start, i): valid, not yet appended
    while (i < text.size()) {
        const std::size_t n = utf8_sequence_length(text.substr(i));
        if (n) {
            i += n;
            continue;
        }
        out.append(text.data() + start, text.data() + i);
        out.append(replacement, replacement + 3);
        start = ++i;
    }
    out.append(text.data() + start, text.data() + i);
}

inline std::string valid_utf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    append_valid_utf8(text, out);
    return out;
}

inline bool is_valid_utf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_sequence_length(text.substr(i));
        if (!n) return false;
        i += n;
    }
    return true;
}

}  // namespace puddle
