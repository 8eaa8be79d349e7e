#include "schedule/solar.hpp"

#include <cmath>
#include <numbers>

namespace puddle::schedule {

namespace {

constexpr double deg = std::numbers::pi / 180.0;
constexpr double unix_epoch_julian_day = 2440587.5;
constexpr double j2000 = 2451545.0;
constexpr double horizon_zenith_deg = 90.833;  // 50' below the horizon: radius 16' plus refraction 34'

struct SunAt {
    double declination;       // radians
    double equation_of_time;  // minutes: apparent solar time minus mean solar time
};

// NOAA's spreadsheet, column by column, at one instant (Julian century from J2000).
SunAt sun_at(double julian_day) {
    const double t = (julian_day - j2000) / 36525.0;
    const double mean_longitude = std::fmod(280.46646 + t * (36000.76983 + t * 0.0003032), 360.0);
    const double mean_anomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t);
    const double eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    const double centre = std::sin(mean_anomaly * deg) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                          std::sin(2 * mean_anomaly * deg) * (0.019993 - 0.000101 * t) +
                          std::sin(3 * mean_anomaly * deg) * 0.000289;
    const double omega = 125.04 - 1934.136 * t;
    const double apparent_longitude = mean_longitude + centre - 0.00569 - 0.00478 * std::sin(omega * deg);
    const double mean_obliquity =
        23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
    const double obliquity = mean_obliquity + 0.00256 * std::cos(omega * deg);
    const double declination = std::asin(std::sin(obliquity * deg) * std::sin(apparent_longitude * deg));
    const double y = std::pow(std::tan(obliquity * deg / 2), 2);
    const double l0 = mean_longitude * deg, m = mean_anomaly * deg, e = eccentricity;
    const double eot =
        4.0 / deg *
        (y * std::sin(2 * l0) - 2 * e * std::sin(m) + 4 * e * y * std::sin(m) * std::cos(2 * l0) -
         0.5 * y * y * std::sin(4 * l0) - 1.25 * e * e * std::sin(2 * m));
    return {declination, eot};
}

// Minutes after 0h UTC of `day` (days since 1970) at which the event happens, refined twice at the
// event's own instant: the sun's declination moves up to 0.4 degrees a day.
std::optional<double> event_minutes(long day, Location where, int sign, bool& up_all_day) {
    double minutes = 720.0 - 4.0 * where.longitude_deg;  // first guess: mean solar noon
    for (int pass = 0; pass < 3; ++pass) {
        const SunAt sun = sun_at(unix_epoch_julian_day + static_cast<double>(day) + minutes / 1440.0);
        const double lat = where.latitude_deg * deg;
        const double cos_hour_angle =
            std::cos(horizon_zenith_deg * deg) / (std::cos(lat) * std::cos(sun.declination)) -
            std::tan(lat) * std::tan(sun.declination);
        if (cos_hour_angle < -1.0 || cos_hour_angle > 1.0) {
            up_all_day = cos_hour_angle < -1.0;
            return std::nullopt;
        }
        const double hour_angle_deg = std::acos(cos_hour_angle) / deg;
        const double noon = 720.0 - 4.0 * where.longitude_deg - sun.equation_of_time;
        minutes = noon + sign * 4.0 * hour_angle_deg;
    }
    return minutes;
}

}  // namespace

SunTimes sun_times(Date date, Location where) {
    SunTimes out;
    const long day = days_from_civil(date);
    bool up_rise = false, up_set = false;
    const auto to_seconds = [day](double minutes) {
        return static_cast<double>(day) * 86400.0 + minutes * 60.0;
    };
    if (auto m = event_minutes(day, where, -1, up_rise)) out.sunrise = to_seconds(*m);
    if (auto m = event_minutes(day, where, +1, up_set)) out.sunset = to_seconds(*m);
    out.up_all_day = !out.sunrise && !out.sunset && up_rise && up_set;
    return out;
}

long days_from_civil(Date date) {
    const long y = date.year - (date.month <= 2 ? 1 : 0);
    const long era = (y >= 0 ? y : y - 399) / 400;
    const long yoe = y - era * 400;
    const long mp = (date.month + 9) % 12;  // March = 0
    const long doy = (153 * mp + 2) / 5 + date.day - 1;
    const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

Date civil_from_days(long days) {
    days += 719468;
    const long era = (days >= 0 ? days : days - 146096) / 146097;
    const long doe = days - era * 146097;
    const long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const long mp = (5 * doy + 2) / 153;
    const int day = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
    const int month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
    return {static_cast<int>(yoe + era * 400 + (month <= 2 ? 1 : 0)), month, day};
}

}  // namespace puddle::schedule
