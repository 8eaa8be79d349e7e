#pragma once
// Sunrise and sunset for a date and place, by NOAA's solar-position equations (the NOAA Global
// Monitoring Laboratory's "Solar Calculator" spreadsheet, after Jean Meeus, "Astronomical Algorithms",
// 1991). Sunrise and sunset are when the sun's upper limb meets a level horizon, with the standard
// 34' of refraction: a solar zenith of 90.833 degrees. Accurate to about a minute between latitudes
// 60 N and 60 S for years 1800 to 2100; nearer the poles the times depend sharply on the atmosphere.

#include <optional>

namespace puddle::schedule {

struct Location {
    double latitude_deg = 0;   // north positive, -90 to 90
    double longitude_deg = 0;  // east positive, -180 to 180
};

// A proleptic Gregorian calendar date.
struct Date {
    int year = 2000;
    int month = 1;  // 1 to 12
    int day = 1;    // 1 to 31
};

struct SunTimes {
    // Seconds since the Unix epoch (UTC). Empty when the sun does not cross the horizon that day
    // (polar day: up all day; polar night: never up).
    std::optional<double> sunrise;
    std::optional<double> sunset;
    bool up_all_day = false;  // with both empty: polar day rather than polar night
};

// The sunrise and sunset that belong to `date` at `where`, for the date as a day of UTC centred on
// the place's solar noon (so the events of one calendar day of local time, for any inhabited time zone).
SunTimes sun_times(Date date, Location where);

// Days since 1970-01-01 of a Gregorian date (negative before), and back: the civil-from-days algorithm
// of Howard Hinnant, "chrono-Compatible Low-Level Date Algorithms".
long days_from_civil(Date date);
Date civil_from_days(long days);

}  // namespace puddle::schedule
