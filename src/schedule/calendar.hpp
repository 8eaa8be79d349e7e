#pragma once
// When schedule entries are active: the time rules of `[[schedule]]` (days, a window `from`..`to` or an
// instant `at`, times of the clock or of sunrise and sunset with an offset), evaluated in local time
// from the system's time zone database (TZ, /etc/localtime), daylight saving included.
//
// Rules, as docs/schedules.md states them:
// - `days` names the days a window starts (or an instant fires) on; a window whose `to` is not after
//   its `from` (as written, for two clock times) ends on the next day (`from = "23:00"`, `to = "07:00"`).
// - One rule for the days the clocks move, as RFC 5545 and java.time have it: a clock time is read with
//   the UTC offset in force before the change. So a time that does not exist (skipped when the clocks go
//   forward) is moved forward by the gap (02:30 in a 02:00-03:00 gap is 03:30), and one that happens
//   twice (when they go back) happens the first time. A window's length then differs from other days'
//   by at most the clock change (02:00 to 03:00 is empty on the spring day and two hours in autumn).
// - A window that is empty on a day (from and to the same instant) does not happen that day.
// - An instant entry stays active until another instant entry fires.
// - Several active entries apply in file order, so the later entry in the file wins.
// - A sunrise or sunset that does not happen (polar day or night) skips that day's occurrence.

#include <bitset>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "schedule/solar.hpp"
#include "util/result.hpp"

namespace puddle::schedule {

// Weekdays, bit 0 = Sunday .. bit 6 = Saturday (as struct tm's tm_wday).
using DaySet = std::bitset<7>;

// "daily", "weekdays", "weekends", or a comma-separated list of days and ranges: "mon-fri", "sat,sun",
// "fri-mon" (ranges wrap past Sunday). Names are three letters or in full, in any case.
// Errors: the message names the text that is not a day and the accepted forms.
Result<DaySet> parse_days(std::string_view text);

struct TimeOfDay {
    enum class Anchor { clock, sunrise, sunset };
    Anchor anchor = Anchor::clock;
    int minutes = 0;  // clock: minutes after midnight (0 to 1440); sunrise/sunset: offset, -720 to 720
    bool operator==(const TimeOfDay&) const = default;
};

// "18:00", "7:05", "24:00" (the end of the day), "sunrise", "sunset", "sunset-00:30", "sunrise+1:15".
// Errors: the message names the text and the accepted forms.
Result<TimeOfDay> parse_time_of_day(std::string_view text);
std::string to_string(const TimeOfDay& t);

// The time part of one schedule entry: a window (from and to) or an instant (at).
struct Rule {
    DaySet days = DaySet().set();
    std::optional<TimeOfDay> from, to, at;
    bool uses_sun() const;
};

// A change of which entries are active.
struct Transition {
    double at = 0;   // seconds since the Unix epoch (UTC)
    int entry = -1;  // the entry that starts, ends or fires then
    enum class Kind { starts, ends, fires } kind = Kind::starts;
};

class Calendar {
public:
    // `where` is needed only when a rule uses sunrise or sunset (check with needs_location()).
    explicit Calendar(std::vector<Rule> rules, std::optional<Location> where = std::nullopt);
    bool needs_location() const;

    // The entries active at `t` (seconds since the Unix epoch), in file order.
    std::vector<int> active_at(double t) const;
    // The first transition after `t` within the next eight days (none when no entry ever happens).
    std::optional<Transition> next_transition(double t) const;
    // The last transition at or before `t` within the previous eight days.
    std::optional<Transition> last_transition(double t) const;

    const std::vector<Rule>& rules() const { return rules_; }

private:
    std::optional<double> resolve(long local_day, const TimeOfDay& when) const;
    void occurrences(long first_day, long last_day, std::vector<Transition>& out) const;
    std::vector<Rule> rules_;
    std::optional<Location> where_;
};

// Local calendar helpers over the system's time zone database (they read TZ as localtime_r does).
long local_day(double t);                  // days since 1970-01-01 of t's local date
int weekday(long day);                     // 0 = Sunday
double local_time(long day, int minutes);  // the UTC instant of a local clock time (rules above)

}  // namespace puddle::schedule
