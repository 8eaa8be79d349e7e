#include "params/config_loader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "params/knob_spec_parse.hpp"
#include "params/schedule_spec_parse.hpp"
#include "params/toml_limits.hpp"
#include "params/toml_syntax_error.hpp"
#include "params/toml_value.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

namespace {

// Every key of a file: the valid ones in `config`, one error per bad one (with its line).
struct Parsed {
    Config config;
    std::vector<std::pair<int, Error>> problems;
};

// Reads every key of `text`. Fails only where no key can be trusted: past the input limits, or not TOML
// (then `syntax_error_line`, when given, is the line a limit was met on or toml++ stopped at).
Result<Parsed> parse_all(std::string_view text, std::string_view path, int* syntax_error_line = nullptr) {
    // A limit met on some line is, for the keys before it, like a syntax error there (the saved state
    // keeps them).
    if (auto r = check_toml_limits(text, path, syntax_error_line); !r) return r.error();
    Parsed out;
    Config& config = out.config;
    config.path = std::string(path);
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        if (syntax_error_line) *syntax_error_line = static_cast<int>(e.source().begin.line);
        const int line = static_cast<int>(e.source().begin.line);
        return make_error(ExitCode::Config, "config: {}:{}: {}", path, line,
                          explain_toml_error(text, line, e.description()));
    }
    auto problem = [&](int line, Error e) { out.problems.emplace_back(line, std::move(e)); };
    for (auto&& [section_key, section_node] : root) {
        if (section_key.str() == "preset") {
            auto name = section_node.value_exact<std::string>();
            if (!name || name->empty())
                problem(
                    toml_line(section_node),
                    make_error(ExitCode::Config,
                               "config: {}:{}: preset must be a preset's name, e.g. preset = \"downpour\"",
                               path, toml_line(section_node)));
            else
                config.preset = *name, config.preset_line = toml_line(section_node);
            continue;
        }
        if (section_key.str() == "remote" && !section_node.is_table()) {
            const toml::array* names = section_node.as_array();
            bool ok = names != nullptr;
            if (names)
                for (const toml::node& n : *names) {
                    const auto name = n.value_exact<std::string>();
                    const ParamDecl* d = name ? find_param(*name) : nullptr;
                    if (d)
                        config.remote.push_back(d->id);
                    else
                        ok = false;
                }
            if (!ok)
                problem(toml_line(section_node),
                        make_error(ExitCode::Config,
                                   "config: {}:{}: remote must list parameter names, e.g. remote = "
                                   "[\"rain.intensity\"]",
                                   path, toml_line(section_node)));
            continue;
        }
        if (section_key.str() == "knob") {
            const toml::array* knobs = section_node.as_array();
            if (!knobs || !knobs->is_array_of_tables()) {
                problem(toml_line(section_node),
                        make_error(ExitCode::Config, "config: {}:{}: knobs are written as [[knob]] tables",
                                   path, toml_line(section_node)));
                continue;
            }
            if (knobs->size() > max_knobs) {
                problem(toml_line(section_node),
                        make_error(ExitCode::Config, "config: {}:{}: {} [[knob]] tables; the limit is {}",
                                   path, toml_line(section_node), knobs->size(), max_knobs));
                continue;
            }
            int index = 0;
            for (const toml::node& k : *knobs) {
                auto knob = parse_knob(*k.as_table(), path, ++index);
                if (!knob)
                    problem(toml_line(k), knob.error());
                else
                    config.knobs.push_back(std::move(*knob));
            }
            continue;
        }
        if (section_key.str() == "schedule") {
            const toml::array* entries = section_node.as_array();
            if (!entries || !entries->is_array_of_tables()) {
                problem(toml_line(section_node),
                        make_error(ExitCode::Config,
                                   "config: {}:{}: schedule entries are written as [[schedule]] tables", path,
                                   toml_line(section_node)));
                continue;
            }
            if (entries->size() > max_schedule_entries) {
                problem(toml_line(section_node),
                        make_error(ExitCode::Config, "config: {}:{}: {} [[schedule]] tables; the limit is {}",
                                   path, toml_line(section_node), entries->size(), max_schedule_entries));
                continue;
            }
            int number = 0;
            for (const toml::node& t : *entries) {
                auto entry = parse_schedule_entry(*t.as_table(), path, ++number);
                if (!entry)
                    problem(toml_line(t), entry.error());
                else
                    config.schedule.push_back(std::move(*entry));
            }
            continue;
        }
        if (section_key.str() == "location" && section_node.is_table()) {
            auto location = parse_location(*section_node.as_table(), path);
            if (!location)
                problem(toml_line(section_node), location.error());
            else
                config.location = *location;
            continue;
        }
        const toml::table* section = section_node.as_table();
        if (!section) {
            const std::string key(section_key.str());
            problem(toml_line(section_node),
                    make_error(ExitCode::Config,
                               "config: {}:{}: '{}' must be inside a [section] (did you mean '{}'?)", path,
                               toml_line(section_node), safe_quote(key), nearest_param_name(key)));
            continue;
        }
        for (auto&& [key, node] : *section) {
            const std::string name = fmt::format("{}.{}", section_key.str(), key.str());
            const ParamDecl* d = find_param(name);
            if (!d) {
                problem(toml_line(node),
                        make_error(ExitCode::Config, "config: {}:{}: unknown key '{}' (did you mean '{}'?)",
                                   path, toml_line(node), safe_quote(name), nearest_param_name(name)));
                continue;
            }
            auto value = toml_param_value(*d, node);
            if (value) {
                if (auto ok = validate(*d, *value); !ok) value = ok.error();
            }
            if (!value) {
                problem(toml_line(node), make_error(ExitCode::Config, "config: {}:{}: {}", path,
                                                    toml_line(node), value.error().message));
                continue;
            }
            config.entries.push_back({d->id, std::move(*value), toml_line(node)});
        }
    }
    if (!config.location)
        for (const ScheduleEntry& e : config.schedule)
            if (e.rule.uses_sun())
                problem(e.line,
                        make_error(ExitCode::Config,
                                   "config: {}:{}: schedule[{}]: sunrise and sunset need a [location] "
                                   "with latitude and longitude, e.g. [location] latitude = 52.52, "
                                   "longitude = 13.40",
                                   path, e.line, e.number));
    // toml++ visits keys in name order; report problems and keep entries in file order, as people read it.
    std::stable_sort(out.problems.begin(), out.problems.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::sort(config.entries.begin(), config.entries.end(),
              [](const ConfigEntry& a, const ConfigEntry& b) { return a.line < b.line; });
    return out;
}

}  // namespace

Result<Config> parse_config(std::string_view text, std::string_view path) {
    auto parsed = parse_all(text, path);
    if (!parsed) return parsed.error();
    if (!parsed->problems.empty()) return parsed->problems.front().second;
    return std::move(parsed->config);
}

Result<PartialConfig> parse_config_keeping_valid(std::string_view text, std::string_view path) {
    int broken_line = 0;
    auto parsed = parse_all(text, path, &broken_line);
    std::optional<std::string> syntax_error;  // stays unset when the text is TOML to the end
    if (!parsed && broken_line > 1) {
        // Not TOML from some line on (a hand edit gone wrong): the keys before it are still good.
        std::size_t cut = 0;
        for (int line = 1; line < broken_line && cut != std::string_view::npos; ++line) {
            cut = text.find('\n', cut);
            if (cut != std::string_view::npos) ++cut;
        }
        if (cut != std::string_view::npos) {
            syntax_error =
                fmt::format("{}; the keys from line {} on are dropped", parsed.error().message, broken_line);
            parsed = parse_all(text.substr(0, cut), path);
        }
    }
    if (!parsed) return parsed.error();
    PartialConfig out{std::move(parsed->config), {}, std::move(syntax_error)};
    for (auto& [line, e] : parsed->problems) out.dropped.push_back(std::move(e.message));
    return out;
}

Result<Config> load_config_file(const std::string& path) {
    auto text = read_toml_file(path);
    if (!text) return text.error();
    return parse_config(*text, path);
}

void apply_config(const Config& config, Params& params, ParamSource source) {
    for (const ConfigEntry& e : config.entries) params.set(e.id, e.value, source);
}

Result<ConfigEntry> parse_assignment(std::string_view assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos)
        return make_error(ExitCode::Config, "--set {}: expected name=value, e.g. --set rain.drop_count=20",
                          safe_quote(assignment));
    const std::string_view name = assignment.substr(0, eq);
    const ParamDecl* d = find_param(name);
    if (!d)
        return make_error(ExitCode::Config, "--set {}: unknown parameter '{}' (did you mean '{}'?)",
                          safe_quote(assignment), safe_quote(name), nearest_param_name(name));
    auto value = parse_value(*d, assignment.substr(eq + 1));
    if (!value) return make_error(ExitCode::Config, "--set: {}", value.error().message);
    return ConfigEntry{d->id, std::move(value).value(), 0};
}

}  // namespace puddle::params
