// [[schedule]] and [location] in the config: what each key becomes, and one clear error per mistake,
// naming the file:line, the entry, the key and the accepted forms; a bad entry refuses the whole file.
#include "params/schedule_spec_parse.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "params/config_loader.hpp"
#include "support/parsed_config.hpp"

namespace puddle::params {
namespace {

std::string error_of(const char* text) {
    auto c = parse_config(text, "night.toml");
    EXPECT_FALSE(c) << text;
    return c ? std::string() : c.error().message;
}

TEST(ScheduleSpecParse, AnEntryBecomesItsRuleAndItsValues) {
    const Config c = test::parsed_config(R"(
[rain]
intensity = 0.3
[[schedule]]
days = "mon-fri"
from = "23:00"
to = "07:00"
display = "off"
[[schedule]]
at = "18:30"
preset = "calm"
set = { "rain.intensity" = 0.8, look.vignette = 1.0 }
brightness = 0.4
)");
    ASSERT_EQ(c.schedule.size(), 2u);
    const ScheduleEntry& night = c.schedule[0];
    EXPECT_EQ(night.number, 1);
    EXPECT_EQ(night.line, 4);
    EXPECT_EQ(night.rule.days, schedule::DaySet("0111110"));
    EXPECT_EQ(night.rule.from, (schedule::TimeOfDay{schedule::TimeOfDay::Anchor::clock, 23 * 60}));
    EXPECT_EQ(night.rule.to, (schedule::TimeOfDay{schedule::TimeOfDay::Anchor::clock, 7 * 60}));
    EXPECT_FALSE(night.rule.at);
    ASSERT_EQ(night.values.size(), 1u);
    EXPECT_EQ(night.values[0], (ScheduledValue{ParamId::display_power, false}));

    const ScheduleEntry& evening = c.schedule[1];
    EXPECT_EQ(evening.number, 2);
    EXPECT_TRUE(evening.rule.days.all());  // days defaults to daily
    EXPECT_EQ(evening.rule.at, (schedule::TimeOfDay{schedule::TimeOfDay::Anchor::clock, 18 * 60 + 30}));
    EXPECT_EQ(evening.preset, "calm");
    // A quoted name and a dotted key (nested tables to TOML) mean the same; brightness comes last.
    const std::vector<ScheduledValue> set{{ParamId::look_vignette, 1.0f}, {ParamId::rain_intensity, 0.8f}};
    ASSERT_EQ(evening.values.size(), 3u);
    EXPECT_TRUE(std::is_permutation(set.begin(), set.end(), evening.values.begin()));
    EXPECT_EQ(evening.values[2], (ScheduledValue{ParamId::display_brightness, 0.4f}));
    ASSERT_EQ(c.entries.size(), 1u);  // the [rain] key is still the config's own
}

TEST(ScheduleSpecParse, SunTimesNeedALocationAndTakeIt) {
    const Config c = test::parsed_config(
        "[location]\nlatitude = 52.52\nlongitude = 13\n[[schedule]]\nfrom = \"sunset-00:30\"\nto = "
        "\"sunrise\"\nbrightness = 0.5\n");
    ASSERT_TRUE(c.location);
    EXPECT_DOUBLE_EQ(c.location->where.latitude_deg, 52.52);
    EXPECT_DOUBLE_EQ(c.location->where.longitude_deg, 13.0);
    ASSERT_EQ(c.schedule.size(), 1u);
    EXPECT_EQ(c.schedule[0].rule.from, (schedule::TimeOfDay{schedule::TimeOfDay::Anchor::sunset, -30}));

    EXPECT_EQ(error_of("[[schedule]]\nat = \"sunset\"\ndisplay = \"off\"\n"),
              "config: night.toml:1: schedule[1]: sunrise and sunset need a [location] with latitude and "
              "longitude, e.g. [location] latitude = 52.52, longitude = 13.40");
}

TEST(ScheduleSpecParse, EachMistakeNamesTheLineTheEntryTheKeyAndTheForms) {
    const std::string ok = "[[schedule]]\nfrom = \"23:00\"\nto = \"07:00\"\ndisplay = \"off\"\n";
    EXPECT_EQ(
        error_of((ok + "[[schedule]]\nat = \"08:00\"\ncolour = 1\n").c_str()),
        "config: night.toml:7: schedule[2]: unknown key 'colour'; a [[schedule]] table takes days, from "
        "and to, or at; and preset, set, display or brightness");
    EXPECT_EQ(
        error_of("[[schedule]]\nfrom = \"25:00\"\nto = \"07:00\"\ndisplay = \"off\"\n"),
        "config: night.toml:2: schedule[1]: from: time \"25:00\" is not a time of day; use HH:MM (00:00 "
        "to 24:00), sunrise or sunset, optionally +HH:MM or -HH:MM");
    EXPECT_EQ(error_of("[[schedule]]\ndays = \"mon-fry\"\nat = \"07:00\"\ndisplay = \"on\"\n"),
              "config: night.toml:2: schedule[1]: days = \"mon-fry\": \"fry\" is not a day; use daily, "
              "weekdays, weekends, or days and ranges such as mon-fri or sat,sun");
    EXPECT_EQ(
        error_of("[[schedule]]\nfrom = \"23:00\"\ndisplay = \"off\"\n"),
        "config: night.toml:1: schedule[1]: a window needs both from and to, e.g. from = \"23:00\", to = "
        "\"07:00\"");
    EXPECT_EQ(error_of("[[schedule]]\nfrom = \"23:00\"\nto = \"07:00\"\nat = \"12:00\"\ndisplay = \"off\"\n"),
              "config: night.toml:4: schedule[1]: give a window (from and to) or an instant (at), not both");
    EXPECT_EQ(error_of("[[schedule]]\nat = \"12:00\"\n"),
              "config: night.toml:1: schedule[1]: nothing to apply: give preset, set, display = \"off\" or "
              "brightness");
    EXPECT_EQ(error_of("[[schedule]]\nat = \"12:00\"\ndisplay = \"dim\"\n"),
              "config: night.toml:3: schedule[1]: display = 'dim': use \"off\" or \"on\"");
    EXPECT_EQ(
        error_of("[[schedule]]\nat = \"12:00\"\nbrightness = 1.5\n"),
        "config: night.toml:3: schedule[1]: brightness = 1.5: a number from 0 (black) to 1 (unchanged)");
    EXPECT_EQ(error_of("[[schedule]]\nat = \"12:00\"\nset = { \"rain.intensty\" = 0.8 }\n"),
              "config: night.toml:3: schedule[1]: set: unknown parameter 'rain.intensty' (did you mean "
              "'rain.intensity'?)");
    EXPECT_EQ(error_of("[[schedule]]\nat = \"12:00\"\nset = { \"rain.intensity\" = 9.0 }\n"),
              "config: night.toml:3: schedule[1]: set: rain.intensity = 9 is out of range: allowed a number "
              "from 0 to 4 height");
    EXPECT_EQ(error_of("[location]\nlatitude = 95\nlongitude = 0\n"),
              "config: night.toml:2: [location] latitude = 95: allowed degrees from -90 to 90");
    EXPECT_EQ(error_of("schedule = 3\n"),
              "config: night.toml:1: schedule entries are written as [[schedule]] tables");
}

TEST(ScheduleSpecParse, TomlTimesAreTakenAsClockTimes) {
    const Config c = test::parsed_config("[[schedule]]\nfrom = 23:00:00\nto = 07:15:00\ndisplay = \"off\"\n");
    ASSERT_EQ(c.schedule.size(), 1u);
    EXPECT_EQ(c.schedule[0].rule.to, (schedule::TimeOfDay{schedule::TimeOfDay::Anchor::clock, 7 * 60 + 15}));
}

}  // namespace
}  // namespace puddle::params
