#pragma once
// Whether the TZ environment variable names a time zone the C library can find.
//
// glibc takes a TZ it cannot resolve as UTC, using the text as the zone's abbreviation and saying nothing
// (TZ=Europe/Berln shows UTC labelled "Europe"), so a schedule would run hours off without a word. The
// forms it accepts are those of the glibc manual ("Specifying the Time Zone with TZ") and tzset(3):
// unset (the system's /etc/localtime), empty (UTC), a POSIX rule such as "CET-1CEST,M3.5.0,M10.5.0/3"
// (a name, then an offset), or a zone file name, optionally after ':', relative to TZDIR
// (default /usr/share/zoneinfo) or absolute.

#include <optional>
#include <string>
#include <string_view>

namespace puddle::schedule {

// One line saying what is wrong with `tz` (the value of TZ; nullptr when unset) and what local time is then,
// or nothing when the C library can resolve it. `zoneinfo_dir` is where zone names are looked up.
std::optional<std::string> time_zone_problem(const char* tz, std::string_view zoneinfo_dir);

// The same for this process: TZ from the environment, zone names under TZDIR or /usr/share/zoneinfo.
std::optional<std::string> time_zone_problem();

}  // namespace puddle::schedule
