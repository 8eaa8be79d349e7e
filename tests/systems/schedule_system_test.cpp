// The schedule layer with an injected wall clock and TZ set: windows past midnight, weekdays, both
// daylight-saving changes, a sunset entry, overlapping entries (the later wins), a knob override that
// holds until the next transition, and --print-config naming the entry.
#include "systems/tuning/schedule_system.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <thread>

#include "params/param_docs.hpp"
#include "schedule/solar.hpp"
#include "schedule/tz_guard.hpp"
#include "support/parsed_config.hpp"
#include "support/test_support.hpp"

namespace puddle::systems {
namespace {

using params::ParamId;
using params::ParamSource;

// A local clock time as a UTC instant (mktime), in the zone the test set.
constexpr auto local = test::local_instant;

struct Rig {
    explicit Rig(const char* config_text) : tuning(params::ParamLayers(params::Presets::load({}), {})) {
        auto r = tuning.layers.set_config(test::parsed_config(config_text));
        EXPECT_TRUE(r) << r.error().message;
        params.replace_with(tuning.layers.compose());
    }
    // One frame's schedule step at `t`, and live tuning's, which acts on what the schedule asked.
    bool at(double t) {
        const bool asked = schedule_step(run, tuning, inbox, t);
        live_tuning_step(inbox, tuning, params, t);
        return asked;
    }
    // The config file becomes `text` and is reloaded, as an edit or SIGHUP does.
    void reload(const std::string& text) {
        tuning.config_path = dir.write("puddle.toml", text);
        EXPECT_TRUE(reload_config(tuning));
    }
    test::TempDir dir;
    bool power() const { return params.get<ParamId::display_power>(); }
    LiveTuning tuning;
    TuningInbox inbox;
    params::Params params;
    ScheduleRun run;
};

constexpr const char* night_off = R"(
[[schedule]]
from = "23:00"
to = "07:00"
display = "off"
)";

TEST(ScheduleSystem, AWindowPastMidnightSwitchesAtItsEdgesAndOnlyThenDoesWork) {
    test::TzGuard tz("Europe/Berlin");
    Rig rig(night_off);
    EXPECT_FALSE(rig.at(local(2026, 6, 5, 22, 59)));  // first evaluation: nothing active, nothing changes
    EXPECT_TRUE(rig.power());
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, local(2026, 6, 5, 23, 0));  // the next transition, cached
    EXPECT_FALSE(rig.at(local(2026, 6, 5, 22, 59) + 30));                 // before it: no work
    EXPECT_TRUE(rig.at(local(2026, 6, 5, 23, 0)));
    EXPECT_FALSE(rig.power());
    EXPECT_EQ(rig.params.source(ParamId::display_power), ParamSource::Schedule);
    EXPECT_FALSE(rig.at(local(2026, 6, 6, 6, 59)));  // still off after midnight
    EXPECT_FALSE(rig.power());
    EXPECT_TRUE(rig.at(local(2026, 6, 6, 7, 0)));
    EXPECT_TRUE(rig.power());
    EXPECT_EQ(rig.params.source(ParamId::display_power), ParamSource::Default);
}

TEST(ScheduleSystem, WeekdayEntriesSkipTheWeekend) {
    test::TzGuard tz("America/New_York");
    Rig rig(
        "[[schedule]]\ndays = \"mon-fri\"\nfrom = \"09:00\"\nto = \"17:00\"\nset = { \"rain.intensity\" = "
        "1.5 }\n");
    rig.at(local(2026, 6, 5, 12, 0));  // Friday
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 1.5f);
    rig.at(local(2026, 6, 5, 17, 0));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 0.3f);  // the default again
    rig.at(local(2026, 6, 6, 12, 0));                                  // Saturday
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 0.3f);
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, local(2026, 6, 8, 9, 0));  // Monday 09:00
}

// The night the clocks go forward (Berlin, 2026-03-29 02:00 -> 03:00) lasts seven hours, the night they go
// back (2026-10-25 03:00 -> 02:00) nine; the screen comes on at 07:00 local time on both mornings.
TEST(ScheduleSystem, BothDaylightSavingChangesKeepLocalTimes) {
    test::TzGuard tz("Europe/Berlin");
    for (int month : {3, 10}) {
        const int day = month == 3 ? 28 : 24;
        Rig rig(night_off);
        rig.at(local(2026, month, day, 23, 30));
        EXPECT_FALSE(rig.power()) << month;
        const double on = local(2026, month, day + 1, 7, 0);
        EXPECT_DOUBLE_EQ(rig.run.next_evaluation, on) << month;
        EXPECT_DOUBLE_EQ(on - local(2026, month, day, 23, 30), (month == 3 ? 6.5 : 8.5) * 3600) << month;
        rig.at(on - 1);
        EXPECT_FALSE(rig.power()) << month;
        rig.at(on);
        EXPECT_TRUE(rig.power()) << month;
    }
}

TEST(ScheduleSystem, ASunsetEntryStartsAtThatDaysSunsetWithItsOffset) {
    test::TzGuard tz("Europe/Berlin");
    Rig rig(R"(
[location]
latitude = 52.52
longitude = 13.40
[[schedule]]
from = "sunset-00:30"
to = "23:00"
set = { "look.vignette" = 1.2 }
brightness = 0.6
)");
    const auto sun = schedule::sun_times({2026, 6, 5}, {52.52, 13.40});
    ASSERT_TRUE(sun.sunset);
    const double start = *sun.sunset - 30 * 60;
    rig.at(start - 60);
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::display_brightness>(), 1.0f);
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, start);
    rig.at(start);
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::display_brightness>(), 0.6f);
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::look_vignette>(), 1.2f);
    rig.at(local(2026, 6, 5, 23, 0));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::display_brightness>(), 1.0f);
}

TEST(ScheduleSystem, OverlappingEntriesApplyInFileOrderSoTheLaterWins) {
    test::TzGuard tz("UTC");
    Rig rig(R"(
[rain]
intensity = 0.5
[[schedule]]
from = "18:00"
to = "23:00"
set = { "rain.intensity" = 1.0, "rain.speed" = 2.0 }
[[schedule]]
from = "20:00"
to = "22:00"
set = { "rain.intensity" = 2.0 }
)");
    rig.at(local(2026, 6, 5, 19, 0));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 1.0f);  // schedule over config
    rig.at(local(2026, 6, 5, 21, 0));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 2.0f);  // the later entry
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_speed>(), 2.0f);      // the earlier one's other value
    // --print-config names the entry each value comes from.
    const std::string printed =
        params::format_effective(rig.params, "", rig.tuning.layers.schedule_entries());
    EXPECT_NE(printed.find("rain.intensity             = 2                        # schedule[2]\n"),
              std::string::npos)
        << printed;
    EXPECT_NE(printed.find("rain.speed                 = 2                        # schedule[1]\n"),
              std::string::npos)
        << printed;
    rig.at(local(2026, 6, 5, 23, 30));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 0.5f);  // the config again
}

// --print-config's header names the preset an active entry applies, not just the config's ("none").
TEST(ScheduleSystem, PrintConfigNamesThePresetOfAnActiveEntry) {
    test::TzGuard tz("UTC");
    Rig rig(R"(
[[schedule]]
from = "18:00"
to = "23:00"
preset = "downpour"
)");
    const auto printed = [&] {
        return params::format_effective(rig.params, rig.tuning.layers.preset_name(),
                                        rig.tuning.layers.schedule_entries(),
                                        rig.tuning.layers.active_schedule_presets());
    };
    rig.at(local(2026, 6, 5, 19, 0));
    EXPECT_NE(printed().find("\n# preset: none; over it, active now: schedule[1] downpour\n"),
              std::string::npos)
        << printed();
    rig.at(local(2026, 6, 5, 23, 30));
    EXPECT_NE(printed().find("\n# preset: none\n"), std::string::npos) << printed();
}

// A knob (or a remote command) set during a window holds until the next transition; then the schedule
// applies again and the knob value is forgotten.
TEST(ScheduleSystem, AKnobChangeHoldsUntilTheNextTransition) {
    test::TzGuard tz("UTC");
    Rig rig(night_off);
    rig.at(local(2026, 6, 5, 23, 30));
    ASSERT_FALSE(rig.power());
    rig.tuning.layers.set_knob(ParamId::display_power, true);  // someone switches it on at night
    rig.params.replace_with(rig.tuning.layers.compose());
    EXPECT_TRUE(rig.power());
    EXPECT_FALSE(rig.at(local(2026, 6, 6, 3, 0)));  // no transition: the knob holds
    EXPECT_TRUE(rig.power());
    EXPECT_TRUE(rig.at(local(2026, 6, 6, 7, 0)));  // the window ends: the knob value is forgotten
    EXPECT_FALSE(rig.tuning.layers.knob(ParamId::display_power));
    EXPECT_TRUE(rig.tuning.state_unsaved());  // and the saved state forgets it too
    EXPECT_TRUE(rig.power());
    EXPECT_EQ(rig.params.source(ParamId::display_power), ParamSource::Default);
    rig.at(local(2026, 6, 6, 23, 0));
    EXPECT_FALSE(rig.power());  // the next night is off again

    // A knob value on a parameter no transition's entry sets is kept.
    rig.tuning.layers.set_knob(ParamId::rain_speed, 3.0f);
    rig.at(local(2026, 6, 7, 7, 0));
    EXPECT_TRUE(rig.tuning.layers.knob(ParamId::rain_speed));
}

// A value set over MQTT shares the knob level, and holds the same way: until the next transition of an
// entry that sets it, then it is forgotten, in the layers and in the saved state.
TEST(ScheduleSystem, ARemoteChangeHoldsUntilTheNextTransitionToo) {
    test::TzGuard tz("UTC");
    Rig rig(R"(
[[schedule]]
from = "18:00"
to = "22:00"
set = { "rain.intensity" = 0.8 }
)");
    rig.at(local(2026, 6, 5, 19, 0));
    ASSERT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 0.8f);
    rig.tuning.layers.set_remote(ParamId::rain_intensity, 0.1f);
    rig.params.replace_with(rig.tuning.layers.compose());
    EXPECT_EQ(rig.params.source(ParamId::rain_intensity), ParamSource::Remote);
    EXPECT_FALSE(rig.at(local(2026, 6, 5, 21, 0)));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::rain_intensity>(), 0.1f)
        << "no transition: the remote value holds";
    EXPECT_TRUE(rig.at(local(2026, 6, 5, 22, 0)));
    EXPECT_FALSE(rig.tuning.layers.knob(ParamId::rain_intensity));
    EXPECT_FALSE(rig.tuning.layers.is_remote(ParamId::rain_intensity));
    EXPECT_EQ(rig.tuning.layers.state_text().find("rain.intensity"), std::string::npos);
    EXPECT_EQ(rig.params.source(ParamId::rain_intensity), ParamSource::Default);
}

TEST(ScheduleSystem, AReloadReevaluatesWithoutForgettingKnobs) {
    test::TzGuard tz("UTC");
    Rig rig(night_off);
    rig.at(local(2026, 6, 5, 12, 0));
    rig.tuning.layers.set_knob(ParamId::display_power, false);
    rig.reload("[[schedule]]\nfrom = \"11:00\"\nto = \"13:00\"\nbrightness = 0.5\n");
    EXPECT_TRUE(rig.at(local(2026, 6, 5, 12, 0) + 1));
    EXPECT_FLOAT_EQ(rig.params.get<ParamId::display_brightness>(), 0.5f);
    EXPECT_TRUE(rig.tuning.layers.knob(ParamId::display_power));  // a reload is no transition
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, local(2026, 6, 5, 13, 0));
}

// `timedatectl set-timezone` while running (here TZ, the injectable source): at a reload the schedule is
// evaluated again in the new zone at once, and without one within a minute (the look then runs on a worker
// thread). The old code kept the zone it started with until a restart.
TEST(ScheduleSystem, ATimeZoneChangeIsEvaluatedAgainAtAReloadAndWithinAMinute) {
    test::TzGuard tz("Europe/Berlin");
    Rig rig(night_off);
    ZoneCheck zone("/nonexistent/localtime");
    double now = local(2026, 6, 5, 22, 0);
    WallClock clock;
    clock.now_ns = [&] { return static_cast<std::int64_t>(now) * ns_per_second; };
    const auto frame = [&] {
        schedule_system(clock, zone, rig.run, rig.tuning, rig.inbox);
        live_tuning_step(rig.inbox, rig.tuning, rig.params, now);
    };
    frame();
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, local(2026, 6, 5, 23, 0));
    const double berlin_23 = rig.run.next_evaluation;
    ::setenv("TZ", "America/New_York", 1);  // no tzset(): the schedule must look again itself
    now += 1;
    frame();
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, berlin_23) << "not looked at again before a minute";
    now += zone_check_seconds;
    for (int i = 0; i < 500 && rig.run.next_evaluation == berlin_23; ++i) {
        frame();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, berlin_23 + 6 * 3600) << "23:00 in New York";
    EXPECT_TRUE(rig.power()) << "22:00 in Berlin is 16:00 in New York";
    // Back to Berlin with a reload (SIGHUP): at once, on that frame.
    ::setenv("TZ", "Europe/Berlin", 1);
    rig.reload(night_off);
    frame();
    EXPECT_DOUBLE_EQ(rig.run.next_evaluation, berlin_23);
}

// The schedule changes nothing itself: it asks live tuning through the inbox, as every other source does,
// and the change is in Params once live tuning has acted on it.
TEST(ScheduleSystem, AsksLiveTuningThroughTheInbox) {
    test::TzGuard tz("UTC");
    Rig rig(night_off);
    rig.at(local(2026, 6, 5, 12, 0));
    ASSERT_TRUE(rig.power());
    ASSERT_TRUE(schedule_step(rig.run, rig.tuning, rig.inbox, local(2026, 6, 5, 23, 0)));
    ASSERT_EQ(rig.inbox.requests.size(), 1u);
    const auto* asked = std::get_if<SetSchedule>(&rig.inbox.requests[0]);
    ASSERT_NE(asked, nullptr);
    EXPECT_EQ(asked->active, std::vector<int>{0});
    EXPECT_EQ(asked->reason,
              "schedule: schedule[1] (daily from 23:00 to 07:00) starts");  // 1-based, as in the file
    EXPECT_TRUE(rig.power()) << "nothing changes before live tuning acts";
    EXPECT_TRUE(rig.tuning.layers.active_schedule().empty());
    live_tuning_step(rig.inbox, rig.tuning, rig.params, local(2026, 6, 5, 23, 0));
    EXPECT_FALSE(rig.power());
    EXPECT_TRUE(rig.inbox.requests.empty());
    // Nothing due: nothing asked.
    EXPECT_FALSE(schedule_step(rig.run, rig.tuning, rig.inbox, local(2026, 6, 6, 1, 0)));
    EXPECT_TRUE(rig.inbox.requests.empty());
}

TEST(ScheduleSystem, TheWallClockGoingBackIsEvaluatedAgain) {
    test::TzGuard tz("UTC");
    Rig rig(night_off);
    rig.at(local(2026, 6, 6, 8, 0));
    EXPECT_TRUE(rig.power());
    EXPECT_TRUE(rig.at(local(2026, 6, 6, 6, 0)));  // an NTP step back into the night
    EXPECT_FALSE(rig.power());
}

}  // namespace
}  // namespace puddle::systems
