#pragma once
// A `[[schedule]]` table of the config as data: when it is active (a schedule::Rule) and what applies
// while it is (a preset and parameter values). `display = "off"` and `brightness = 0.4` are written as
// the parameter values they stand for (display.power, display.brightness), so the schedule layer is one
// list of values per entry. docs/schedules.md states the rules.

#include <optional>
#include <string>
#include <vector>

#include "params/registry.hpp"
#include "schedule/calendar.hpp"
#include "schedule/solar.hpp"

namespace puddle::params {

// At most this many [[schedule]] tables (each adds its occurrences to every evaluation).
inline constexpr std::size_t max_schedule_entries = 64;

struct ScheduledValue {
    ParamId id;
    ParamValue value;
    bool operator==(const ScheduledValue&) const = default;
};

struct ScheduleEntry {
    int number = 0;  // 1 for the first [[schedule]] table: schedule[1] in messages and --print-config
    int line = 0;    // where the table starts
    schedule::Rule rule;
    std::optional<std::string> preset;   // `preset = "calm"`: its values apply while the entry is active
    std::vector<ScheduledValue> values;  // `set = {...}`, then `display`, then `brightness`
};

// `[location]`: where sunrise and sunset are computed for.
struct ScheduleLocation {
    schedule::Location where;
    int line = 0;
};

}  // namespace puddle::params
