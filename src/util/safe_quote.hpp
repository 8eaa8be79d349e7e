#pragma once
// Text from a user's file or message, made fit to quote inside one log line: control characters become
// '?', so a name cannot break the line or move the terminal's cursor, and a long one is clipped with its
// length said, so a 40 KB key written by mistake (or by a fuzzer) gives one readable line, not 40 KB.

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace puddle {

// At most `limit` bytes of `text` (cut before a UTF-8 continuation byte, so no character is split),
// then "... (N bytes)" when it was longer; control characters (below 0x20, and 0x7f) as '?'.
inline std::string safe_quote(std::string_view text, std::size_t limit = 64) {
    std::size_t cut = std::min(text.size(), limit);
    while (cut > 0 && cut < text.size() && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    std::string out(text.substr(0, cut));
    std::replace_if(
        out.begin(), out.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; },
        '?');
    if (cut < text.size()) out += fmt::format("... ({} bytes)", text.size());
    return out;
}

}  // namespace puddle
