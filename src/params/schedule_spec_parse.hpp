#pragma once
// Reads `[[schedule]]` and `[location]` tables (params/schedule_spec.hpp). Errors name the file and line,
// the entry (schedule[N], counted from 1), the key and the forms it accepts.
#include <toml++/toml.h>

#include <string_view>

#include "params/schedule_spec.hpp"
#include "util/result.hpp"

namespace puddle::params {

// The `number`th [[schedule]] table. Keys: days (default daily), from and to, or at; preset, set,
// display ("on" or "off"), brightness (0 to 1). At least one of the last four.
Result<ScheduleEntry> parse_schedule_entry(const toml::table& table, std::string_view path, int number);
// `[location] latitude = 52.52  longitude = 13.40` (degrees, north and east positive).
Result<ScheduleLocation> parse_location(const toml::table& table, std::string_view path);

}  // namespace puddle::params
