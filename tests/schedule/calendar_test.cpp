// The schedule's time rules in local time: days and ranges, windows past midnight, instants, overlap,
// daylight-saving days (both changes, in London and New York), sunrise and sunset with offsets.
#include "schedule/calendar.hpp"

#include <gtest/gtest.h>

#include <ctime>

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
    EXPECT_EQ(start->at, utc(2026, 3, 29, 1, 0)) << "a skipped time happens when the clocks jump";
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
