#include "schedule/calendar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <ctime>

namespace puddle::schedule {

namespace {

constexpr std::string_view day_names[7] = {"sun", "mon", "tue", "wed", "thu", "fri", "sat"};
constexpr std::string_view full_day_names[7] = {"sunday",   "monday", "tuesday", "wednesday",
                                                "thursday", "friday", "saturday"};
constexpr std::string_view days_forms =
    "daily, weekdays, weekends, or days and ranges such as mon-fri or sat,sun";
constexpr std::string_view time_forms =
    "HH:MM (00:00 to 24:00), sunrise or sunset, optionally +HH:MM or -HH:MM";
constexpr int lookaround_days = 8;  // a week of any pattern, plus a window that began the day before

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::optional<int> day_index(std::string_view name) {
    for (int i = 0; i < 7; ++i)
        if (name == day_names[i] || name == full_day_names[i]) return i;
    return std::nullopt;
}

// "HH:MM" with 1 or 2 hour digits and 2 minute digits; minutes after midnight.
std::optional<int> parse_hh_mm(std::string_view s) {
    const auto colon = s.find(':');
    if (colon == std::string_view::npos || colon == 0 || colon > 2 || s.size() != colon + 3)
        return std::nullopt;
    int h = 0, m = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (i != colon && !std::isdigit(static_cast<unsigned char>(s[i]))) return std::nullopt;
    std::from_chars(s.data(), s.data() + colon, h);
    std::from_chars(s.data() + colon + 1, s.data() + s.size(), m);
    if (m > 59) return std::nullopt;
    return h * 60 + m;
}

tm local_tm(std::time_t t) {
    tm out{};
    localtime_r(&t, &out);
    return out;
}

}  // namespace

Result<DaySet> parse_days(std::string_view text) {
    const std::string all = lower(trim(text));
    if (all == "daily" || all == "every day") return DaySet().set();
    if (all == "weekdays") return DaySet("0111110");
    if (all == "weekends") return DaySet("1000001");
    DaySet days;
    std::string_view rest = all;
    while (true) {
        const auto comma = rest.find(',');
        const std::string_view item = trim(rest.substr(0, comma));
        const auto dash = item.find('-');
        const std::string_view first_name = trim(item.substr(0, dash));
        const std::string_view last_name =
            dash == std::string_view::npos ? first_name : trim(item.substr(dash + 1));
        const auto first = day_index(first_name), last = day_index(last_name);
        if (!first || !last)
            return make_error(ExitCode::Config, "schedule: days = \"{}\": \"{}\" is not a day; use {}", text,
                              first ? last_name : first_name, days_forms);
        for (int d = *first;; d = (d + 1) % 7) {
            days.set(static_cast<std::size_t>(d));
            if (d == *last) break;
        }
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    return days;
}

Result<TimeOfDay> parse_time_of_day(std::string_view text) {
    const std::string s = lower(trim(text));
    const auto bad = [&] {
        return make_error(ExitCode::Config, "schedule: time \"{}\" is not a time of day; use {}", text,
                          time_forms);
    };
    for (auto [name, anchor] :
         {std::pair{"sunrise", TimeOfDay::Anchor::sunrise}, std::pair{"sunset", TimeOfDay::Anchor::sunset}}) {
        const std::string_view n = name;
        if (s.rfind(n, 0) != 0) continue;
        std::string_view offset = trim(std::string_view(s).substr(n.size()));
        if (offset.empty()) return TimeOfDay{anchor, 0};
        const int sign = offset.front() == '-' ? -1 : offset.front() == '+' ? 1 : 0;
        if (sign == 0) return bad();
        const auto minutes = parse_hh_mm(trim(offset.substr(1)));
        if (!minutes || *minutes > 720) return bad();
        return TimeOfDay{anchor, sign * *minutes};
    }
    const auto minutes = parse_hh_mm(s);
    if (!minutes || *minutes > 24 * 60) return bad();
    return TimeOfDay{TimeOfDay::Anchor::clock, *minutes};
}

std::string to_string(const TimeOfDay& t) {
    const int a = std::abs(t.minutes);
    switch (t.anchor) {
        case TimeOfDay::Anchor::clock:
            return fmt::format("{:02}:{:02}", a / 60, a % 60);
        case TimeOfDay::Anchor::sunrise:
        case TimeOfDay::Anchor::sunset: {
            const char* name = t.anchor == TimeOfDay::Anchor::sunrise ? "sunrise" : "sunset";
            if (t.minutes == 0) return name;
            return fmt::format("{}{}{:02}:{:02}", name, t.minutes < 0 ? '-' : '+', a / 60, a % 60);
        }
    }
    return {};
}

bool Rule::uses_sun() const {
    for (const auto& t : {from, to, at})
        if (t && t->anchor != TimeOfDay::Anchor::clock) return true;
    return false;
}

long local_day(double t) {
    const tm l = local_tm(static_cast<std::time_t>(std::floor(t)));
    return days_from_civil({l.tm_year + 1900, l.tm_mon + 1, l.tm_mday});
}

int weekday(long day) {
    return static_cast<int>(((day % 7) + 11) % 7);
}  // 1970-01-01 was a Thursday

double local_time(long day, int minutes) {
    day += minutes / 1440;  // 24:00 is the next day's midnight
    minutes %= 1440;
    const Date d = civil_from_days(day);
    const int h = minutes / 60, m = minutes % 60;
    // The UTC offsets in force around that day: the clock time read with each, kept where it round-trips.
    const std::time_t wall = static_cast<std::time_t>(day * 86400 + minutes * 60);  // as if UTC
    std::time_t best = 0;
    bool found = false;
    long offsets[2] = {local_tm(wall - 86400).tm_gmtoff, local_tm(wall + 86400).tm_gmtoff};
    for (long off : offsets) {
        const std::time_t cand = wall - off;
        const tm l = local_tm(cand);
        if (l.tm_hour == h && l.tm_min == m && l.tm_mday == d.day && (!found || cand < best)) {
            best = cand;
            found = true;
        }
    }
    if (found) return static_cast<double>(best);
    // Skipped by the clocks going forward: read with the offset in force before the jump, so it is moved
    // forward by the gap (02:30 in a 02:00-03:00 gap is 03:30). The jump is found by bisection.
    std::time_t lo = std::min(wall - offsets[0], wall - offsets[1]),
                hi = std::max(wall - offsets[0], wall - offsets[1]);
    const long before = local_tm(lo).tm_gmtoff;
    while (hi - lo > 1) {
        const std::time_t mid = lo + (hi - lo) / 2;
        (local_tm(mid).tm_gmtoff == before ? lo : hi) = mid;
    }
    return static_cast<double>(wall - local_tm(hi - 1).tm_gmtoff);
}

Calendar::Calendar(std::vector<Rule> rules, std::optional<Location> where)
    : rules_(std::move(rules)), where_(where) {}

bool Calendar::needs_location() const {
    return std::any_of(rules_.begin(), rules_.end(), [](const Rule& r) { return r.uses_sun(); });
}

std::optional<double> Calendar::resolve(long day, const TimeOfDay& when) const {
    if (when.anchor == TimeOfDay::Anchor::clock) return local_time(day, when.minutes);
    if (!where_) return std::nullopt;
    const SunTimes sun = sun_times(civil_from_days(day), *where_);
    const auto& event = when.anchor == TimeOfDay::Anchor::sunrise ? sun.sunrise : sun.sunset;
    if (!event) return std::nullopt;
    return *event + when.minutes * 60.0;
}

// Every start, end and firing of every entry for windows and instants that begin on local days
// first_day..last_day, in time order (ties in file order).
void Calendar::occurrences(long first_day, long last_day, std::vector<Transition>& out) const {
    for (long day = first_day; day <= last_day; ++day) {
        for (int i = 0; i < static_cast<int>(rules_.size()); ++i) {
            const Rule& r = rules_[static_cast<std::size_t>(i)];
            if (!r.days.test(static_cast<std::size_t>(weekday(day)))) continue;
            if (r.at) {
                if (auto t = resolve(day, *r.at)) out.push_back({*t, i, Transition::Kind::fires});
                continue;
            }
            if (!r.from || !r.to) continue;
            const auto start = resolve(day, *r.from);
            auto end = resolve(day, *r.to);
            // Two clock times compare as written: on a day the clocks move, 02:00 to 03:00 may resolve to
            // one instant (02:00 skipped), and that window is empty that day, not a day long.
            const bool clock_times =
                r.from->anchor == TimeOfDay::Anchor::clock && r.to->anchor == TimeOfDay::Anchor::clock;
            if (start && end && (clock_times ? r.to->minutes <= r.from->minutes : *end <= *start))
                end = resolve(day + 1, *r.to);
            if (!start || !end || *end <= *start) continue;
            out.push_back({*start, i, Transition::Kind::starts});
            out.push_back({*end, i, Transition::Kind::ends});
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Transition& a, const Transition& b) { return a.at < b.at; });
}

std::vector<int> Calendar::active_at(double t) const {
    const long today = local_day(t);
    std::vector<Transition> events;
    occurrences(today - lookaround_days, today + 1, events);
    std::vector<bool> active(rules_.size(), false);
    // Windows: active inside [start, end) of an occurrence.
    for (std::size_t k = 0; k < events.size(); ++k) {
        const Transition& e = events[k];
        if (e.kind != Transition::Kind::starts || e.at > t) continue;
        for (std::size_t j = k + 1; j < events.size(); ++j) {
            if (events[j].entry != e.entry || events[j].kind != Transition::Kind::ends) continue;
            if (t < events[j].at) active[static_cast<std::size_t>(e.entry)] = true;
            break;
        }
    }
    // Instants: the latest firing at or before t, and any that fired at that same moment.
    double last = -1e300;
    for (const Transition& e : events)
        if (e.kind == Transition::Kind::fires && e.at <= t) last = std::max(last, e.at);
    for (const Transition& e : events)
        if (e.kind == Transition::Kind::fires && e.at == last)
            active[static_cast<std::size_t>(e.entry)] = true;
    std::vector<int> out;
    for (std::size_t i = 0; i < active.size(); ++i)
        if (active[i]) out.push_back(static_cast<int>(i));
    return out;
}

std::optional<Transition> Calendar::next_transition(double t) const {
    const long today = local_day(t);
    std::vector<Transition> events;
    occurrences(today - 1, today + lookaround_days, events);
    for (const Transition& e : events)
        if (e.at > t) return e;
    return std::nullopt;
}

std::optional<Transition> Calendar::last_transition(double t) const {
    const long today = local_day(t);
    std::vector<Transition> events;
    occurrences(today - lookaround_days, today + 1, events);
    std::optional<Transition> last;
    for (const Transition& e : events)
        if (e.at <= t) last = e;
    return last;
}

}  // namespace puddle::schedule
