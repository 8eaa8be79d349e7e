#pragma once
// Reading a `[[knob]]` table; used by the config loader only (it keeps toml++ out of other headers).

#include <toml++/toml.h>

#include <string_view>

#include "params/knob_spec.hpp"
#include "util/result.hpp"

namespace puddle::params {

// `index` counts the [[knob]] tables from 1, for messages.
Result<KnobSpec> parse_knob(const toml::table& table, std::string_view path, int index);

}  // namespace puddle::params
