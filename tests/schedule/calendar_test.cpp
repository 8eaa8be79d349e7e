// The schedule's time rules in local time: days and ranges, windows past midnight, instants, overlap,
// daylight-saving days (both changes, in London, Berlin and New York, from the system's tz database), sunrise
// and sunset with offsets.
#include "schedule/calendar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <filesystem>

#include "schedule/tz_guard.hpp"

namespace puddle::schedule {
namespace {

using test::TzGuard;

// A local clock time as a UTC instant (mktime), in the zone the test set.
constexpr auto at = test::local_instant;

double utc(int y, int mo, int d, int h, int mi) {
    return static_cast<double>(days_from_civil({y, mo, d}) * 86400 + h * 3600 + mi * 60);
}

TimeOfDay t(const char* s) {
    auto r = parse_time_of_day(s);
    EXPECT_TRUE(r) << s << ": " << r.error().message;
    return r ? *r : TimeOfDay{};
}

Rule window(const char* days, const char* from, const char* to) {
    auto d = parse_days(days);
    EXPECT_TRUE(d) << d.error().message;
    return Rule{.days = *d, .from = t(from), .to = t(to)};
}

Rule instant(const char* days, const char* when) {
    auto d = parse_days(days);
    EXPECT_TRUE(d);
    return Rule{.days = *d, .at = t(when)};
}

using Active = std::vector<int>;

DaySet days(const char* text) {
    auto d = parse_days(text);
    EXPECT_TRUE(d) << text;
    return d ? *d : DaySet();
}

TEST(ScheduleDays, NamesRangesAndWords) {
    EXPECT_EQ(days("mon-fri"), DaySet("0111110"));
    EXPECT_EQ(days("sat,sun"), DaySet("1000001"));
    EXPECT_EQ(days("Sat, Sunday"), DaySet("1000001"));
    EXPECT_EQ(days("fri-mon"), DaySet("1100011")) << "a range wraps past Sunday";
    EXPECT_EQ(days("daily"), DaySet("1111111"));
    EXPECT_EQ(days("weekdays"), days("mon-fri"));
    EXPECT_EQ(days("wed"), DaySet("0001000"));
    auto bad = parse_days("mon-funday");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("\"funday\" is not a day"), std::string::npos) << bad.error().message;
    EXPECT_NE(bad.error().message.find("mon-fri"), std::string::npos) << "names the accepted forms";
    EXPECT_FALSE(parse_days(""));
    EXPECT_FALSE(parse_days("mon,,fri"));
}

TEST(ScheduleTimes, ClockAndSunWithOffsets) {
    EXPECT_EQ(t("18:00"), (TimeOfDay{TimeOfDay::Anchor::clock, 1080}));
    EXPECT_EQ(t("7:05"), (TimeOfDay{TimeOfDay::Anchor::clock, 425}));
    EXPECT_EQ(t("24:00"), (TimeOfDay{TimeOfDay::Anchor::clock, 1440}));
    EXPECT_EQ(t("sunset"), (TimeOfDay{TimeOfDay::Anchor::sunset, 0}));
    EXPECT_EQ(t("sunset-00:30"), (TimeOfDay{TimeOfDay::Anchor::sunset, -30}));
    EXPECT_EQ(t("Sunrise + 1:15"), (TimeOfDay{TimeOfDay::Anchor::sunrise, 75}));
    EXPECT_EQ(to_string(t("sunset-00:30")), "sunset-00:30");
    EXPECT_EQ(to_string(t("7:05")), "07:05");
    for (const char* bad :
         {"25:00", "24:01", "18:60", "18", "1800", "noon", "sunset-13:00", "sunset 00:30", "-1:00", ""}) {
        auto r = parse_time_of_day(bad);
        EXPECT_FALSE(r) << bad;
        if (!r) {
            EXPECT_NE(r.error().message.find("HH:MM"), std::string::npos) << r.error().message;
        }
    }
}

TEST(ScheduleCalendar, AWindowPastMidnightBelongsToTheDayItStarts) {
    TzGuard tz("Europe/London");
    // Screen off on weekday nights: from Friday 23:00 it runs into Saturday, but no window starts Saturday.
    Calendar cal({window("mon-fri", "23:00", "07:00")});
    // 2026-01-09 is a Friday.
    EXPECT_EQ(cal.active_at(at(2026, 1, 9, 22, 59)), Active{});
    EXPECT_EQ(cal.active_at(at(2026, 1, 9, 23, 0)), Active{0});
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 6, 59)), Active{0}) << "Friday's window, on Saturday morning";
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 7, 0)), Active{});
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 23, 30)), Active{}) << "no window starts on Saturday";
    EXPECT_EQ(cal.active_at(at(2026, 1, 12, 2, 0)), Active{}) << "nor on Sunday";
    EXPECT_EQ(cal.active_at(at(2026, 1, 12, 23, 1)), Active{0}) << "Monday";
    auto next = cal.next_transition(at(2026, 1, 10, 12, 0));
    ASSERT_TRUE(next);
    EXPECT_EQ(next->at, at(2026, 1, 12, 23, 0)) << "from Saturday noon the next change is Monday night";
    EXPECT_EQ(next->kind, Transition::Kind::starts);
    auto last = cal.last_transition(at(2026, 1, 10, 12, 0));
    ASSERT_TRUE(last);
    EXPECT_EQ(last->at, at(2026, 1, 10, 7, 0));
    EXPECT_EQ(last->kind, Transition::Kind::ends);
}

TEST(ScheduleCalendar, LaterEntriesInTheFileWinWhereWindowsOverlap) {
    TzGuard tz("Europe/London");
    Calendar cal({window("daily", "18:00", "23:00"), window("sat,sun", "20:00", "22:00")});
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 19, 0)), Active{0});
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 21, 0)), (Active{0, 1}))
        << "in file order: the later one applies last";
    EXPECT_EQ(cal.active_at(at(2026, 1, 9, 21, 0)), Active{0}) << "Friday";
}

TEST(ScheduleCalendar, AnInstantHoldsUntilAnotherInstantFires) {
    TzGuard tz("Europe/London");
    Calendar cal({instant("daily", "07:00"), instant("daily", "19:00")});
    EXPECT_EQ(cal.active_at(at(2026, 1, 9, 12, 0)), Active{0});
    EXPECT_EQ(cal.active_at(at(2026, 1, 9, 20, 0)), Active{1});
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 3, 0)), Active{1}) << "the evening's instant holds overnight";
    EXPECT_EQ(cal.active_at(at(2026, 1, 10, 7, 0)), Active{0});
    auto next = cal.next_transition(at(2026, 1, 9, 12, 0));
    ASSERT_TRUE(next);
    EXPECT_EQ(next->at, at(2026, 1, 9, 19, 0));
    EXPECT_EQ(next->kind, Transition::Kind::fires);
    EXPECT_EQ(next->entry, 1);
}

TEST(ScheduleCalendar, TheSpringClockChangeInLondon) {
    TzGuard tz("Europe/London");
    // 2026-03-29: 01:00 GMT becomes 02:00 BST; 01:30 never happens.
    Calendar cal({window("daily", "01:30", "03:00"), instant("daily", "07:00")});
    auto start = cal.next_transition(utc(2026, 3, 29, 0, 0));
    ASSERT_TRUE(start);
    EXPECT_EQ(start->at, utc(2026, 3, 29, 1, 30)) << "a skipped time is moved forward by the gap: 02:30 BST";
    EXPECT_EQ(start->entry, 0);
    EXPECT_EQ(cal.active_at(utc(2026, 3, 29, 1, 30)), (Active{0, 1})) << "02:30 BST";
    EXPECT_EQ(cal.active_at(utc(2026, 3, 29, 2, 0)), Active{1}) << "03:00 BST: ended";
    // 07:00 local both sides of the change: 07:00 UTC before, 06:00 UTC after.
    EXPECT_EQ(cal.next_transition(utc(2026, 3, 28, 5, 0))->at, utc(2026, 3, 28, 7, 0));
    EXPECT_EQ(cal.next_transition(utc(2026, 3, 29, 5, 0))->at, utc(2026, 3, 29, 6, 0));
}

TEST(ScheduleCalendar, TheAutumnClockChangeInLondon) {
    TzGuard tz("Europe/London");
    // 2026-10-25: 02:00 BST becomes 01:00 GMT; 01:30 happens twice: the first time counts.
    Calendar cal({window("daily", "01:30", "23:00")});
    auto start = cal.next_transition(utc(2026, 10, 24, 23, 0));
    ASSERT_TRUE(start);
    EXPECT_EQ(start->at, utc(2026, 10, 25, 0, 30)) << "01:30 BST, not 01:30 GMT an hour later";
    // A window over the night of the change lasts an hour longer in real time.
    Calendar night({window("daily", "22:00", "06:00")});
    auto begin = night.next_transition(utc(2026, 10, 24, 12, 0));
    ASSERT_TRUE(begin);
    auto end = night.next_transition(begin->at);
    ASSERT_TRUE(end);
    EXPECT_EQ(end->at - begin->at, 9 * 3600.0);
}

TEST(ScheduleCalendar, NewYorkClockChangesAndMidnight) {
    TzGuard tz("America/New_York");
    // 2026-03-08: 02:00 EST becomes 03:00 EDT. 2026-11-01: 02:00 EDT becomes 01:00 EST.
    Calendar cal({window("daily", "23:00", "07:00")});
    auto begin = cal.next_transition(utc(2026, 3, 7, 12, 0));
    ASSERT_TRUE(begin);
    EXPECT_EQ(begin->at, utc(2026, 3, 8, 4, 0)) << "23:00 EST on the 7th";
    auto end = cal.next_transition(begin->at);
    ASSERT_TRUE(end);
    EXPECT_EQ(end->at, utc(2026, 3, 8, 11, 0)) << "07:00 EDT on the 8th";
    EXPECT_EQ(end->at - begin->at, 7 * 3600.0) << "one hour shorter that night";
    auto fall_begin = cal.next_transition(utc(2026, 10, 31, 12, 0));
    auto fall_end = cal.next_transition(fall_begin->at);
    EXPECT_EQ(fall_end->at - fall_begin->at, 9 * 3600.0) << "one hour longer";
    EXPECT_EQ(cal.active_at(utc(2026, 11, 1, 6, 30)), Active{0}) << "01:30 EST, the second time";
}

// A zone's clock-change days in 2026 (all Sundays) and the local days before them.
struct ClockChange {
    const char* zone;
    Date day;
    double utc_jump;  // the instant the clocks move
};
const ClockChange clock_changes[] = {
    {"Europe/Berlin", {2026, 3, 29}, utc(2026, 3, 29, 1, 0)},     // 02:00 CET becomes 03:00 CEST
    {"Europe/Berlin", {2026, 10, 25}, utc(2026, 10, 25, 1, 0)},   // 03:00 CEST becomes 02:00 CET
    {"America/New_York", {2026, 3, 8}, utc(2026, 3, 8, 7, 0)},    // 02:00 EST becomes 03:00 EDT
    {"America/New_York", {2026, 11, 1}, utc(2026, 11, 1, 6, 0)},  // 02:00 EDT becomes 01:00 EST
};

bool zoneinfo_has(const char* zone) {
    return std::filesystem::exists(std::filesystem::path("/usr/share/zoneinfo") / zone);
}

// The length of the window a Sunday-only rule opens on `day` (0 when none opens that day).
double window_length_on(const Calendar& cal, long day) {
    const double midnight = local_time(day, 0);
    const auto start = cal.next_transition(midnight - 1);
    if (!start || start->kind != Transition::Kind::starts || start->at >= local_time(day + 1, 0)) return 0;
    const auto end = cal.next_transition(start->at);
    return end ? end->at - start->at : 0;
}

// The field report: display off from 02:00 to 03:00, inside the hour the clocks skip. That day's window is
// empty (both ends are 03:00), not 24 hours long (the old "to not after from ends the next day" on the
// resolved instants made the screen black all Sunday).
TEST(ScheduleCalendar, AWindowInsideTheSkippedHourIsEmptyThatDayNotADayLong) {
    for (const ClockChange& c : clock_changes) {
        if (!zoneinfo_has(c.zone)) GTEST_SKIP() << "no /usr/share/zoneinfo/" << c.zone << " (tzdata)";
        if (c.day.month > 6) continue;  // the spring days
        TzGuard tz(c.zone);
        Calendar cal({window("daily", "02:00", "03:00")});
        const long day = days_from_civil(c.day);
        EXPECT_EQ(cal.active_at(c.utc_jump + 1), Active{}) << c.zone << ": 03:00 local, just after the jump";
        EXPECT_EQ(cal.active_at(c.utc_jump + 6 * 3600), Active{}) << c.zone << ": that Sunday's morning";
        EXPECT_EQ(cal.active_at(c.utc_jump + 12 * 3600), Active{}) << c.zone << ": that Sunday's afternoon";
        EXPECT_EQ(cal.active_at(local_time(day - 1, 150)), Active{0}) << c.zone << ": 02:30 on Saturday";
        EXPECT_EQ(cal.active_at(local_time(day + 1, 150)), Active{0}) << c.zone << ": 02:30 on Monday";
        const auto next = cal.next_transition(c.utc_jump - 2 * 3600);
        ASSERT_TRUE(next);
        EXPECT_EQ(next->at, local_time(day + 1, 120)) << c.zone << ": the next start is Monday's 02:00";
    }
}

// One rule for every clock time on a change day, read with the offset in force before the change: a
// skipped one is moved forward by the gap, one that happens twice happens the first time.
TEST(ScheduleCalendar, SkippedTimesMoveForwardByTheGapAndRepeatedOnesHappenTheFirstTime) {
    if (!zoneinfo_has("Europe/Berlin") || !zoneinfo_has("America/New_York")) GTEST_SKIP() << "no tzdata";
    {
        TzGuard tz("Europe/Berlin");
        EXPECT_EQ(local_time(days_from_civil({2026, 3, 29}), 150), utc(2026, 3, 29, 1, 30)) << "03:30 CEST";
        EXPECT_EQ(local_time(days_from_civil({2026, 3, 29}), 120), utc(2026, 3, 29, 1, 0)) << "03:00 CEST";
        EXPECT_EQ(local_time(days_from_civil({2026, 10, 25}), 150), utc(2026, 10, 25, 0, 30)) << "02:30 CEST";
        Calendar cal({instant("sun", "02:30"), instant("sun", "12:00")});
        const auto fires = cal.next_transition(utc(2026, 3, 29, 0, 0));
        ASSERT_TRUE(fires);
        EXPECT_EQ(fires->at, utc(2026, 3, 29, 1, 30)) << "an instant at 02:30 fires at 03:30 CEST";
    }
    {
        TzGuard tz("America/New_York");
        EXPECT_EQ(local_time(days_from_civil({2026, 3, 8}), 135), utc(2026, 3, 8, 7, 15)) << "03:15 EDT";
        EXPECT_EQ(local_time(days_from_civil({2026, 11, 1}), 90), utc(2026, 11, 1, 5, 30)) << "01:30 EDT";
    }
}

// Every window with ends on the half hours around the changes (and midday, late evening, 24:00), on each
// change day in Berlin and New York: its length differs from the same window's a week earlier by at most
// the hour the clocks moved.
TEST(ScheduleCalendar, AWindowsLengthChangesByAtMostTheClockChange) {
    std::vector<int> ends{12 * 60, 23 * 60, 24 * 60};
    for (int m = 0; m <= 5 * 60; m += 30) ends.push_back(m);
    for (const ClockChange& c : clock_changes) {
        if (!zoneinfo_has(c.zone)) GTEST_SKIP() << "no /usr/share/zoneinfo/" << c.zone << " (tzdata)";
        TzGuard tz(c.zone);
        const long day = days_from_civil(c.day);
        for (const int from : ends)
            for (const int to : ends) {
                const Calendar cal({Rule{.days = days("sun"),
                                         .from = TimeOfDay{TimeOfDay::Anchor::clock, from},
                                         .to = TimeOfDay{TimeOfDay::Anchor::clock, to}}});
                const double usual = window_length_on(cal, day - 7), changed = window_length_on(cal, day);
                EXPECT_LE(std::abs(changed - usual), 3600.0)
                    << c.zone << " " << c.day.year << "-" << c.day.month << "-" << c.day.day << " from "
                    << to_string(*cal.rules()[0].from) << " to " << to_string(*cal.rules()[0].to) << ": "
                    << changed / 3600 << " h, usually " << usual / 3600 << " h";
            }
    }
}

TEST(ScheduleCalendar, SunsetWithAnOffsetFollowsTheSeasons) {
    TzGuard tz("Europe/London");
    const Location london{51.51, -0.13};
    Calendar cal({window("daily", "sunset-00:30", "23:00")}, london);
    EXPECT_TRUE(cal.needs_location());
    // Sunset on 1 June 2025 is 21:07 BST, on 1 December 15:57 GMT (published), so the window opens at
    // about 20:37 and 15:27.
    EXPECT_EQ(cal.active_at(at(2025, 6, 1, 20, 30)), Active{});
    EXPECT_EQ(cal.active_at(at(2025, 6, 1, 20, 45)), Active{0});
    EXPECT_EQ(cal.active_at(at(2025, 12, 1, 15, 20)), Active{});
    EXPECT_EQ(cal.active_at(at(2025, 12, 1, 15, 35)), Active{0});
    auto opens = cal.next_transition(at(2025, 6, 1, 12, 0));
    ASSERT_TRUE(opens);
    EXPECT_NEAR(opens->at, at(2025, 6, 1, 20, 37), 120.0);
    // Without a location, a sun-relative window never happens (the config loader refuses it first).
    Calendar blind({window("daily", "sunset", "23:00")});
    EXPECT_EQ(blind.active_at(at(2025, 6, 1, 22, 0)), Active{});
}

TEST(ScheduleCalendar, AWindowFromSunsetToSunriseSpansTheNight) {
    TzGuard tz("Europe/London");
    Calendar cal({window("daily", "sunset", "sunrise")}, Location{51.51, -0.13});
    EXPECT_EQ(cal.active_at(at(2025, 12, 1, 23, 0)), Active{0});
    EXPECT_EQ(cal.active_at(at(2025, 12, 2, 7, 0)), Active{0}) << "before sunrise (about 07:45)";
    EXPECT_EQ(cal.active_at(at(2025, 12, 2, 9, 0)), Active{});
    EXPECT_EQ(cal.active_at(at(2025, 12, 2, 12, 0)), Active{});
}

TEST(ScheduleCalendar, NothingHappensWithoutDays) {
    TzGuard tz("UTC");
    Calendar cal({Rule{.days = DaySet(), .from = t("10:00"), .to = t("11:00")}});
    EXPECT_EQ(cal.active_at(utc(2026, 1, 1, 10, 30)), Active{});
    EXPECT_FALSE(cal.next_transition(utc(2026, 1, 1, 0, 0)));
}

}  // namespace
}  // namespace puddle::schedule
