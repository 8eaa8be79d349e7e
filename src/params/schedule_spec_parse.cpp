#include "params/schedule_spec_parse.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "params/toml_value.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

namespace {

constexpr std::array entry_keys{"days", "from", "to", "at", "preset", "set", "display", "brightness"};
constexpr std::string_view entry_forms = "days, from and to, or at; and preset, set, display or brightness";

// "config: PATH:LINE: schedule[N]: WHAT".
template <class... Args>
Error entry_error(std::string_view path, const toml::node& at, int number, fmt::format_string<Args...> f,
                  Args&&... args) {
    return make_error(ExitCode::Config, "config: {}:{}: schedule[{}]: {}", path, toml_line(at), number,
                      fmt::format(f, std::forward<Args>(args)...));
}

std::string_view without_module(std::string_view message) {
    if (message.starts_with("schedule: ")) message.remove_prefix(10);
    return message;
}

// `from = "18:00"`, `at = "sunset-00:30"`, or a TOML time (`from = 18:00:00`).
Result<schedule::TimeOfDay> time_value(const toml::node& n, std::string_view key, std::string_view path,
                                       int number) {
    if (auto t = n.value_exact<toml::time>())
        return schedule::TimeOfDay{schedule::TimeOfDay::Anchor::clock, t->hour * 60 + t->minute};
    auto text = n.value_exact<std::string>();
    if (!text)
        return entry_error(path, n, number,
                           "{} = {} must be a time in quotes: HH:MM, \"sunrise\" or \"sunset\", "
                           "optionally +HH:MM or -HH:MM",
                           key, safe_quote(toml_text(n)));
    auto t = schedule::parse_time_of_day(*text);
    if (!t) return entry_error(path, n, number, "{}: {}", key, without_module(t.error().message));
    return *t;
}

// `set = { "rain.intensity" = 0.8 }`, or with the name as a dotted key (`set = { rain.intensity = 0.8 }`,
// which TOML reads as nested tables).
Result<void> read_set(const toml::table& t, std::string prefix, std::string_view path, int number,
                      std::vector<ScheduledValue>& out) {
    for (auto&& [key, node] : t) {
        const std::string name =
            prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
        const ParamDecl* d = find_param(name);
        if (!d && node.is_table()) {
            if (auto r = read_set(*node.as_table(), name, path, number, out); !r) return r;
            continue;
        }
        if (!d)
            return entry_error(path, node, number, "set: unknown parameter '{}' (did you mean '{}'?)",
                               safe_quote(name), nearest_param_name(name));
        auto value = toml_param_value(*d, node);
        if (value)
            if (auto ok = validate(*d, *value); !ok) value = ok.error();
        if (!value) return entry_error(path, node, number, "set: {}", value.error().message);
        out.push_back({d->id, std::move(*value)});
    }
    return {};
}

}  // namespace

Result<ScheduleEntry> parse_schedule_entry(const toml::table& table, std::string_view path, int number) {
    ScheduleEntry e;
    e.number = number;
    e.line = toml_line(table);
    for (auto&& [key, node] : table)
        if (std::find(entry_keys.begin(), entry_keys.end(), key.str()) == entry_keys.end())
            return entry_error(path, node, number, "unknown key '{}'; a [[schedule]] table takes {}",
                               safe_quote(key.str()), entry_forms);
    if (const toml::node* days = table.get("days")) {
        auto text = days->value_exact<std::string>();
        if (!text)
            return entry_error(path, *days, number, "days = {} must be text such as \"mon-fri\" or \"daily\"",
                               safe_quote(toml_text(*days)));
        auto set = schedule::parse_days(*text);
        if (!set) return entry_error(path, *days, number, "{}", without_module(set.error().message));
        e.rule.days = *set;
    }
    for (auto [key, slot] :
         {std::pair{"from", &e.rule.from}, std::pair{"to", &e.rule.to}, std::pair{"at", &e.rule.at}}) {
        const toml::node* n = table.get(key);
        if (!n) continue;
        auto t = time_value(*n, key, path, number);
        if (!t) return t.error();
        *slot = *t;
    }
    const bool window = e.rule.from || e.rule.to;
    if (window && e.rule.at)
        return entry_error(path, *table.get("at"), number,
                           "give a window (from and to) or an instant (at), not both");
    if (window && (!e.rule.from || !e.rule.to))
        return entry_error(path, table, number,
                           "a window needs both from and to, e.g. from = \"23:00\", "
                           "to = \"07:00\"");
    if (!window && !e.rule.at)
        return entry_error(path, table, number,
                           "no time: give from and to (a window, e.g. \"23:00\" to \"07:00\") or at (an "
                           "instant, e.g. \"sunset\")");
    if (const toml::node* p = table.get("preset")) {
        auto name = p->value_exact<std::string>();
        if (!name || name->empty())
            return entry_error(path, *p, number, "preset must be a preset's name, e.g. preset = \"calm\"");
        e.preset = *name;
    }
    if (const toml::node* s = table.get("set")) {
        if (!s->is_table())
            return entry_error(path, *s, number,
                               "set must be a table of values, e.g. set = {{ \"rain.intensity\" = 0.8 }}");
        if (auto r = read_set(*s->as_table(), "", path, number, e.values); !r) return r.error();
    }
    if (const toml::node* d = table.get("display")) {
        auto text = d->value_exact<std::string>();
        if (!text || (*text != "on" && *text != "off"))
            return entry_error(path, *d, number, "display = {}: use \"off\" or \"on\"",
                               safe_quote(toml_text(*d)));
        e.values.push_back({ParamId::display_power, *text == "on"});
    }
    if (const toml::node* b = table.get("brightness")) {
        const ParamDecl& d = decl(ParamId::display_brightness);
        auto value = toml_param_value(d, *b);
        if (value)
            if (auto ok = validate(d, *value); !ok) value = ok.error();
        if (!value)
            return entry_error(path, *b, number, "brightness = {}: a number from 0 (black) to 1 (unchanged)",
                               safe_quote(toml_text(*b)));
        e.values.push_back({ParamId::display_brightness, std::move(*value)});
    }
    if (!e.preset && e.values.empty())
        return entry_error(path, table, number,
                           "nothing to apply: give preset, set, display = \"off\" or brightness");
    return e;
}

Result<ScheduleLocation> parse_location(const toml::table& table, std::string_view path) {
    ScheduleLocation out;
    out.line = toml_line(table);
    auto fail = [&](const toml::node& at, std::string_view what) {
        return make_error(ExitCode::Config, "config: {}:{}: [location] {}", path, toml_line(at), what);
    };
    for (auto&& [key, node] : table)
        if (key.str() != "latitude" && key.str() != "longitude")
            return fail(node, fmt::format("unknown key '{}'; [location] takes latitude and longitude",
                                          safe_quote(key.str())));
    for (auto [key, limit, slot] : {std::tuple{"latitude", 90.0, &out.where.latitude_deg},
                                    std::tuple{"longitude", 180.0, &out.where.longitude_deg}}) {
        const toml::node* n = table.get(key);
        if (!n)
            return fail(table, fmt::format("needs latitude and longitude in degrees, north and east "
                                           "positive, e.g. latitude = 52.52, longitude = 13.40"));
        std::optional<double> v = n->value_exact<double>();
        if (auto whole = n->value_exact<int64_t>()) v = static_cast<double>(*whole);
        if (!v || !std::isfinite(*v) || std::abs(*v) > limit)
            return fail(*n, fmt::format("{} = {}: allowed degrees from {} to {}", key,
                                        safe_quote(toml_text(*n)), -limit, limit));
        *slot = *v;
    }
    return out;
}

}  // namespace puddle::params
