#include "systems/tuning/schedule_system.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iterator>
#include <utility>
#include <vector>

#include "schedule/time_zone.hpp"

namespace puddle::systems {

namespace {

constexpr double day_seconds = 86400;
constexpr const char* day_names[7] = {"sun", "mon", "tue", "wed", "thu", "fri", "sat"};

std::string days_text(const schedule::DaySet& days) {
    if (days.all()) return "daily";
    std::string out;
    for (int d : {1, 2, 3, 4, 5, 6, 0})  // Monday first, as people write weeks
        if (days.test(static_cast<std::size_t>(d)))
            out += fmt::format("{}{}", out.empty() ? "" : ",", day_names[d]);
    return out;
}

std::string_view kind_text(schedule::Transition::Kind k) {
    switch (k) {
        case schedule::Transition::Kind::starts:
            return "starts";
        case schedule::Transition::Kind::ends:
            return "ends";
        case schedule::Transition::Kind::fires:
            return "fires";
    }
    return "?";
}

// The entries whose knob values a transition from `before` to `after` clears: those that started or
// ended, and an instant that fired again (it stays active, so the sets alone do not show it).
std::vector<int> entries_of_transition(const std::vector<int>& before, const std::vector<int>& after,
                                       const schedule::Transition* fired) {
    std::vector<int> out;
    std::set_symmetric_difference(before.begin(), before.end(), after.begin(), after.end(),
                                  std::back_inserter(out));
    if (fired && std::find(out.begin(), out.end(), fired->entry) == out.end()) out.push_back(fired->entry);
    return out;
}

}  // namespace

std::optional<schedule::Calendar> make_calendar(const params::Config& config) {
    if (config.schedule.empty()) return std::nullopt;
    std::vector<schedule::Rule> rules;
    rules.reserve(config.schedule.size());
    for (const params::ScheduleEntry& e : config.schedule) rules.push_back(e.rule);
    std::optional<schedule::Location> where;
    if (config.location) where = config.location->where;
    return schedule::Calendar(std::move(rules), where);
}

bool schedule_step(ScheduleRun& run, const LiveTuning& tuning, TuningInbox& inbox, double now) {
    const bool reloaded = run.config_generation != tuning.config_generation();
    const bool clock_went_back = run.evaluated && now < run.last_evaluated;
    const bool zone_changed = std::exchange(run.zone_changed, false);
    if (!reloaded && !clock_went_back && !zone_changed && now < run.next_evaluation) return false;
    if (reloaded) {
        run.calendar = make_calendar(tuning.layers.config());
        run.config_generation = tuning.config_generation();
        if (run.calendar && !run.time_zone_checked) {
            run.time_zone_checked = true;
            if (const auto problem = schedule::time_zone_problem()) spdlog::warn("schedule: {}", *problem);
        }
    }
    const params::Config& config = tuning.layers.config();
    std::vector<int> active = run.calendar ? run.calendar->active_at(now) : std::vector<int>{};
    std::optional<schedule::Transition> last, next;
    if (run.calendar) {
        last = run.calendar->last_transition(now);
        next = run.calendar->next_transition(now);
    }
    // Knob values are forgotten at a transition only, not when a reload or a clock step re-evaluates.
    std::vector<int> forget;
    std::string reason = "schedule";
    if (run.evaluated && !reloaded && !clock_went_back && !zone_changed && last &&
        last->at > run.last_evaluated) {
        // A pointer, not a copied optional: GCC 12 at -O3 warned (-Wmaybe-uninitialized) on the copy.
        const schedule::Transition* fired =
            last->kind == schedule::Transition::Kind::fires ? &*last : nullptr;
        forget = entries_of_transition(tuning.layers.active_schedule(), active, fired);
        reason = fmt::format("schedule: {} {}",
                             describe_entry(config.schedule[static_cast<std::size_t>(last->entry)]),
                             kind_text(last->kind));
    }
    const bool changed = active != tuning.layers.active_schedule() || !forget.empty();
    run.evaluated = true;
    run.last_evaluated = now;
    run.next_evaluation = next ? next->at : now + day_seconds;
    if (changed)
        inbox.push(SetSchedule{
            .active = std::move(active), .forget_knobs_of = std::move(forget), .reason = std::move(reason)});
    if (next && (changed || reloaded || zone_changed))
        spdlog::info("schedule: next: {}", describe_transition(config, *next));
    return changed;
}

bool zone_check_step(ZoneCheck& check, std::uint64_t config_generation, double now) {
    std::optional<schedule::Zone> changed;
    if (auto done = check.job.take()) changed = std::move(*done);
    const bool reloaded = std::exchange(check.config_generation, config_generation) != config_generation;
    // Due a minute after the last look, or at once when the wall clock went back past it.
    const bool due = now >= check.next_check || now < check.next_check - zone_check_seconds;
    if (reloaded) {
        if (auto z = check.watch.refresh()) changed = std::move(z);
    } else if (due && !check.job.busy()) {
        check.job.submit([&watch = check.watch](std::stop_token) { return watch.refresh(); });
    }
    if (reloaded || due) check.next_check = now + zone_check_seconds;
    if (!changed) return false;
    spdlog::info("time zone now {}", changed->describe());
    return true;
}

void schedule_system(const WallClock& clock, ZoneCheck& zone, ScheduleRun& run, const LiveTuning& tuning,
                     TuningInbox& inbox) {
    if (zone_check_step(zone, tuning.config_generation(), clock.seconds())) run.zone_changed = true;
    schedule_step(run, tuning, inbox, clock.seconds());
}

void activate_schedule(LiveTuning& tuning, double now) {
    const auto calendar = make_calendar(tuning.layers.config());
    tuning.layers.set_active_schedule(calendar ? calendar->active_at(now) : std::vector<int>{});
}

std::string describe_entry(const params::ScheduleEntry& e) {
    const schedule::Rule& r = e.rule;
    if (r.at)
        return fmt::format("schedule[{}] ({} at {})", e.number, days_text(r.days),
                           schedule::to_string(*r.at));
    return fmt::format("schedule[{}] ({} from {} to {})", e.number, days_text(r.days),
                       r.from ? schedule::to_string(*r.from) : "?", r.to ? schedule::to_string(*r.to) : "?");
}

std::string describe_transition(const params::Config& config, const schedule::Transition& t) {
    if (t.entry < 0 || t.entry >= static_cast<int>(config.schedule.size())) return "none";
    return fmt::format("schedule[{}] {} at {}", config.schedule[static_cast<std::size_t>(t.entry)].number,
                       kind_text(t.kind), local_time_text(t.at));
}

std::string local_time_text(double t) {
    const std::time_t s = static_cast<std::time_t>(std::floor(t));
    tm l{};
    localtime_r(&s, &l);
    char text[64];
    const std::size_t n = std::strftime(text, sizeof text, "%a %Y-%m-%d %H:%M %Z", &l);
    return std::string(text, n);
}

Result<void> add_schedule(ecs::World& world, ecs::Schedule& schedule) {
    if (!world.try_resource<WallClock>()) world.insert_resource<WallClock>();
    world.insert_resource<ScheduleRun>();
    world.insert_resource<ZoneCheck>();
    schedule.add(ecs::Stage::Input, "schedule", schedule_system);
    return {};
}

}  // namespace puddle::systems
