#pragma once
// toml++ stops at the first character it cannot read and says so in its own words, without the key:
// "Error while parsing floating-point: '1e400' could not be interpreted as a value". For someone editing
// a config that is not enough, so the line's key is found again in the text: a number too big for 64
// bits (or for a double) given to a known parameter becomes the registry's own out-of-range message
// ("rain.intensity = 1e400 is out of range: allowed a number from 0 to 4"), and any other error at a
// `key = value` line names the key.

#include <string>
#include <string_view>

namespace puddle::params {

// The dotted key assigned on `line` (1-based) of `text`, with the [table] header above it:
// "rain.intensity" for `intensity = 1e400` under `[rain]`. Empty when the line assigns nothing.
// Simple and quoted keys are understood; a header inside a multi-line string may mislead it, which only
// costs the message its key.
std::string key_at_line(std::string_view text, int line);

// One line for toml++'s `description` of an error at `line` of `text` (without the "config: PATH:LINE: "
// prefix, which the caller adds). The description is quoted safely (util/safe_quote.hpp).
std::string explain_toml_error(std::string_view text, int line, std::string_view description);

}  // namespace puddle::params
