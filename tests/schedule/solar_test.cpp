// NOAA's sunrise and sunset against published tables, within 2 minutes: the U.S. Naval Observatory's for
// Washington and Cape May on the 2002 equinox and for Decorah, Iowa through September; polar day and night
// at Tromso; and the calendar-day arithmetic.
#include "schedule/solar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>

#include "schedule/tz_guard.hpp"

namespace puddle::schedule {
namespace {

// Local clock minutes after midnight of a UTC instant.
double local_minutes(double t) {
    const std::time_t s = static_cast<std::time_t>(std::floor(t));
    tm l{};
    localtime_r(&s, &l);
    return l.tm_hour * 60 + l.tm_min + (t - static_cast<double>(s) + l.tm_sec) / 60.0;
}

struct Published {
    Date date;
    int rise;  // local clock, minutes after midnight
    int set;
};

void expect_within_two_minutes(Location where, const Published& p, const char* place) {
    const SunTimes sun = sun_times(p.date, where);
    ASSERT_TRUE(sun.sunrise && sun.sunset) << place;
    EXPECT_NEAR(local_minutes(*sun.sunrise), p.rise, 2.0)
        << place << " sunrise " << p.date.year << "-" << p.date.month << "-" << p.date.day;
    EXPECT_NEAR(local_minutes(*sun.sunset), p.set, 2.0)
        << place << " sunset " << p.date.year << "-" << p.date.month << "-" << p.date.day;
}

constexpr int hm(int h, int m) {
    return h * 60 + m;
}

TEST(Solar, MatchesTheNavalObservatoryForWashingtonAndCapeMay) {
    test::TzGuard tz("America/New_York");
    // USNO, Wednesday 20 March 2002, Eastern Standard Time.
    expect_within_two_minutes({38.9, -77.0}, {{2002, 3, 20}, hm(6, 12), hm(18, 21)}, "Washington DC");
    expect_within_two_minutes({38.9, -74.9}, {{2002, 3, 20}, hm(6, 4), hm(18, 12)}, "Cape May NJ");
}

TEST(Solar, MatchesTheNavalObservatoryForDecorahThroughSeptember) {
    test::TzGuard tz("America/Chicago");
    // Decorah, Iowa (43.30 N, 91.79 W), September, Central Daylight Time: the U.S. Naval Observatory's
    // figures as tabulated by Luther College
    // (faculty.luther.edu/bernatzr/DecWx/Month09/Data/srssData_09.htm).
    const Location decorah{43.30, -91.79};
    const Published table[] = {
        {{2025, 9, 1}, hm(6, 32), hm(19, 41)},  {{2025, 9, 8}, hm(6, 40), hm(19, 29)},
        {{2025, 9, 15}, hm(6, 47), hm(19, 16)}, {{2025, 9, 22}, hm(6, 55), hm(19, 4)},
        {{2025, 9, 30}, hm(7, 4), hm(18, 49)},
    };
    for (const auto& p : table) expect_within_two_minutes(decorah, p, "Decorah");
}

TEST(Solar, PolarDayAndNightHaveNoSunriseOrSunset) {
    const Location tromso{69.65, 18.96};
    const SunTimes midsummer = sun_times({2025, 6, 21}, tromso);
    EXPECT_FALSE(midsummer.sunrise);
    EXPECT_FALSE(midsummer.sunset);
    EXPECT_TRUE(midsummer.up_all_day);
    const SunTimes midwinter = sun_times({2025, 12, 21}, tromso);
    EXPECT_FALSE(midwinter.sunrise);
    EXPECT_FALSE(midwinter.up_all_day);
    const SunTimes spring = sun_times({2025, 3, 21}, tromso);
    EXPECT_TRUE(spring.sunrise && spring.sunset) << "an ordinary day there";
}

TEST(Solar, SunriseComesBeforeSunsetOnTheSameLocalDayFarFromGreenwich) {
    test::TzGuard tz("Australia/Sydney");
    const SunTimes sun = sun_times({2025, 1, 15}, {-33.87, 151.21});
    ASSERT_TRUE(sun.sunrise && sun.sunset);
    EXPECT_LT(*sun.sunrise, *sun.sunset);
    // Sydney's summer: about 06:00 and 20:10 daylight time (AEDT).
    EXPECT_NEAR(local_minutes(*sun.sunrise), hm(6, 0), 10);
    EXPECT_NEAR(local_minutes(*sun.sunset), hm(20, 10), 10);
}

TEST(Solar, CivilDaysRoundTrip) {
    EXPECT_EQ(days_from_civil({1970, 1, 1}), 0);
    EXPECT_EQ(days_from_civil({2000, 3, 1}), 11017);
    EXPECT_EQ(days_from_civil({1969, 12, 31}), -1);
    for (long d = -800000; d < 800000; d += 997) {
        const Date c = civil_from_days(d);
        EXPECT_EQ(days_from_civil(c), d);
    }
}

}  // namespace
}  // namespace puddle::schedule
