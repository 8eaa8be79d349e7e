#pragma once
// The schedule layer while the display runs: the config's [[schedule]] entries (schedule::Calendar)
// evaluated against the wall clock, in the input stage right before live tuning, which it asks for the
// change (a SetSchedule request in the TuningInbox) as every other source does. It works only at a
// transition (the next one is cached; other frames compare two doubles and allocate nothing), after a
// config reload (seen the frame after live tuning made it), and when the wall clock goes back (an NTP
// correction). At a transition the knob values of the parameters the entries concerned set are forgotten:
// a knob turned during a window holds until the next transition, then the schedule applies again. On a
// wall (wall.clock = "realtime") the change then lands at the wall's next change step, as a reload does.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "params/param_store.hpp"
#include "params/schedule_spec.hpp"
#include "schedule/calendar.hpp"
#include "schedule/zone_watch.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "util/background_job.hpp"

namespace puddle::systems {

// Resource.
struct ScheduleRun {
    std::optional<schedule::Calendar> calendar;           // none when the config has no [[schedule]] table
    std::uint64_t config_generation = ~std::uint64_t{0};  // the LiveTuning::config_generation it was made for
    bool evaluated = false;
    double last_evaluated = 0;
    double next_evaluation = 0;  // the next transition, or a day later when none is in sight
    bool time_zone_checked =
        false;                  // a TZ the C library cannot resolve is logged once, with the first calendar
    bool zone_changed = false;  // set by zone_check_step: evaluated again, as at a reload
};

// Resource: the time zone (schedule/zone_watch.hpp), looked at again at each config reload (on the frame
// thread, which reads the config files then anyway) and every minute on a worker thread (a readlink and a
// stat), so a `timedatectl set-timezone` applies within a minute, or at once with SIGHUP.
struct ZoneCheck {
    explicit ZoneCheck(std::filesystem::path system_zone = "/etc/localtime")
        : watch(std::move(system_zone)) {}
    schedule::ZoneWatch watch;
    BackgroundJob<std::optional<schedule::Zone>> job;  // after `watch`: it goes first, and its job with it
    std::uint64_t config_generation = ~std::uint64_t{0};
    double next_check = 0;  // wall-clock seconds
};
constexpr double zone_check_seconds = 60;

// At a reload (`config_generation` changed) or when a minute has passed (`now`, wall-clock seconds), looks
// at the zone; true when it changed, which is then in force and logged ("time zone now ...").
bool zone_check_step(ZoneCheck& check, std::uint64_t config_generation, double now);

// The calendar of a config's entries (none without entries).
std::optional<schedule::Calendar> make_calendar(const params::Config& config);

// When due (see above), asks live tuning through `inbox` to put the entries active at `now` in force and
// returns true when it asked (the entries in force differ, or a transition forgets knob values); live
// tuning's next step recomposes Params and logs the change ("schedule: schedule[2] ... starts: ...").
bool schedule_step(ScheduleRun& run, const LiveTuning& tuning, TuningInbox& inbox, double now);
// Input stage: schedule_step at the wall clock's time.
// A zone change (zone_check_step) is evaluated again as a reload is: no knob is forgotten.
void schedule_system(const WallClock& clock, ZoneCheck& zone, ScheduleRun& run, const LiveTuning& tuning,
                     TuningInbox& inbox);

// Start-up and --print-config: the entries active at `now`, set in the layers without clearing knobs.
void activate_schedule(LiveTuning& tuning, double now);

// "schedule[2] (mon-fri from 23:00 to 07:00)", "schedule[3] (daily at sunset-00:30)".
std::string describe_entry(const params::ScheduleEntry& entry);
// "schedule[2] ends at Wed 2026-12-02 07:00 CET".
std::string describe_transition(const params::Config& config, const schedule::Transition& transition);
// "Wed 2026-12-02 07:00 CET": local time, as the system's time zone gives it.
std::string local_time_text(double t);

// Inserts WallClock (systems/clock/wall_clock.hpp) and ScheduleRun and adds schedule_system to the input
// stage: add it before live tuning, which acts on its requests in the same frame.
Result<void> add_schedule(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
