#pragma once
// Bounds on every TOML file Puddle reads (the config, presets, the saved state), checked on the raw text
// before toml++ sees it. toml++ 3.3 bounds nested arrays and inline tables (TOML_MAX_NESTED_VALUES) but
// not dotted keys or table headers: `a.a.a. ... .a = 1` 50 000 levels deep overflows the stack (SIGSEGV).
// The limits are far above what a real config needs (its deepest value is a [[knob]] key at 3 levels, its
// longest key under 20 bytes, the shipped config about 19 KiB), so only a broken or hostile file meets them.

#include <cstddef>
#include <string>
#include <string_view>

#include "util/result.hpp"

namespace puddle::params {

struct TomlLimits {
    std::size_t max_bytes = 1024 * 1024;     // the whole file
    std::size_t max_line_bytes = 64 * 1024;  // one line: six 4 KiB cubemap paths fit
    int max_depth = 16;  // levels a value sits below the root: [a.b] c.d = [[1]] is 2 + 2 + 2 = 6
    std::size_t max_key_bytes = 256;  // one dotted key or table header as written
};
inline constexpr TomlLimits toml_limits{};

// Checks `text` against the limits. The error (exit code 2) names the file, the line and the limit:
// "config: /etc/puddle/puddle.toml:3: key nests 50001 levels; the limit is 16". Syntax errors are not
// reported here (toml++ does that with its own words); the scan only has to bound what it can reach.
// `failed_line`, when given, is set to the line a limit was met on (left alone for the file's size).
Result<void> check_toml_limits(std::string_view text, std::string_view path, int* failed_line = nullptr);

// Reads a file of at most toml_limits.max_bytes without reading more than one byte past it (a FIFO or
// /dev/zero named as a config ends too). Errors: "config: PATH: cannot open: why", "config: PATH: larger
// than 1 MiB; the limit is 1048576 bytes".
Result<std::string> read_toml_file(const std::string& path);

}  // namespace puddle::params
