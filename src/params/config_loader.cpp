#include "params/config_loader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "params/knob_spec_parse.hpp"
#include "params/toml_limits.hpp"
#include "params/toml_syntax_error.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

namespace {

int line_of(const toml::node& n) {
    return static_cast<int>(n.source().begin.line);
}

// The value as written, on one line: numbers in their shortest form (1e+300, not toml++'s
// 1.0000000000000001e+300), arrays as [1, 2, 3].
std::string toml_text(const toml::node& n) {
    if (auto i = n.value_exact<int64_t>()) return fmt::format("{}", *i);
    if (auto f = n.value_exact<double>()) return fmt::format("{}", *f);
    if (const toml::array* a = n.as_array()) {
        std::string out = "[";
        for (const toml::node& e : *a) out += (out.size() > 1 ? ", " : "") + toml_text(e);
        return out + "]";
    }
    std::ostringstream out;
    n.visit([&](auto&& v) { out << v; });
    return out.str();
}

// Converts a TOML node to the declared kind. Numbers (toml++ gives int64 or double) are checked against
// the range before they are narrowed (number_value); the error names the key and the value as written.
Result<ParamValue> convert(const ParamDecl& d, const toml::node& n) {
    auto wrong_type = [&] {
        return make_error(ExitCode::Config, "{} = {} has the wrong type: expected {}", d.name,
                          safe_quote(toml_text(n)), describe_range(d));
    };
    auto number = [&]() -> Result<ParamValue> {
        if (auto i = n.value_exact<int64_t>()) return number_value(d, *i);
        if (auto f = n.value_exact<double>()) return number_value(d, *f);
        return wrong_type();
    };
    switch (d.kind) {
        case ParamKind::Bool:
            if (auto b = n.value_exact<bool>()) return ParamValue(*b);
            return wrong_type();
        case ParamKind::Int:
            if (n.is_floating_point()) return wrong_type();  // 2.5 is not an integer, not even 2.0
            return number();
        case ParamKind::Float:
            return number();
        case ParamKind::Vec3:
        case ParamKind::Color: {
            const toml::array* a = n.as_array();
            if (!a || a->size() != 3) return wrong_type();
            glm::vec3 c{};
            for (std::size_t i = 0; i < 3; ++i) {
                const toml::node& e = (*a)[i];
                std::optional<double> x = e.value_exact<double>();
                if (auto whole = e.value_exact<int64_t>()) x = static_cast<double>(*whole);
                if (!x) return wrong_type();
                // Past a float's range is out of range as written, not infinity; validate() checks the rest.
                if (!std::isfinite(static_cast<float>(*x))) return out_of_range(d, toml_text(n));
                c[static_cast<int>(i)] = static_cast<float>(*x);
            }
            return ParamValue(c);
        }
        case ParamKind::Enum:
            if (auto s = n.value_exact<std::string>()) return ParamValue(*s);
            return wrong_type();
        case ParamKind::Path:
            if (auto s = n.value_exact<std::string>()) return ParamValue(*s);
            // Six cubemap faces may be given as an array of paths; they travel joined by '|'.
            if (const toml::array* a = n.as_array(); a && !a->empty()) {
                std::string joined;
                for (const toml::node& e : *a) {
                    auto s = e.value_exact<std::string>();
                    if (!s) return wrong_type();
                    joined += (joined.empty() ? "" : "|") + *s;
                }
                return ParamValue(joined);
            }
            return wrong_type();
    }
    return wrong_type();
}

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
                    line_of(section_node),
                    make_error(ExitCode::Config,
                               "config: {}:{}: preset must be a preset's name, e.g. preset = \"downpour\"",
                               path, line_of(section_node)));
            else
                config.preset = *name, config.preset_line = line_of(section_node);
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
                problem(line_of(section_node),
                        make_error(ExitCode::Config,
                                   "config: {}:{}: remote must list parameter names, e.g. remote = "
                                   "[\"rain.intensity\"]",
                                   path, line_of(section_node)));
            continue;
        }
        if (section_key.str() == "knob") {
            const toml::array* knobs = section_node.as_array();
            if (!knobs || !knobs->is_array_of_tables()) {
                problem(line_of(section_node),
                        make_error(ExitCode::Config, "config: {}:{}: knobs are written as [[knob]] tables",
                                   path, line_of(section_node)));
                continue;
            }
            if (knobs->size() > max_knobs) {
                problem(line_of(section_node),
                        make_error(ExitCode::Config, "config: {}:{}: {} [[knob]] tables; the limit is {}",
                                   path, line_of(section_node), knobs->size(), max_knobs));
                continue;
            }
            int index = 0;
            for (const toml::node& k : *knobs) {
                auto knob = parse_knob(*k.as_table(), path, ++index);
                if (!knob)
                    problem(line_of(k), knob.error());
                else
                    config.knobs.push_back(std::move(*knob));
            }
            continue;
        }
        const toml::table* section = section_node.as_table();
        if (!section) {
            const std::string key(section_key.str());
            problem(line_of(section_node),
                    make_error(ExitCode::Config,
                               "config: {}:{}: '{}' must be inside a [section] (did you mean '{}'?)", path,
                               line_of(section_node), safe_quote(key), nearest_param_name(key)));
            continue;
        }
        for (auto&& [key, node] : *section) {
            const std::string name = fmt::format("{}.{}", section_key.str(), key.str());
            const ParamDecl* d = find_param(name);
            if (!d) {
                problem(line_of(node),
                        make_error(ExitCode::Config, "config: {}:{}: unknown key '{}' (did you mean '{}'?)",
                                   path, line_of(node), safe_quote(name), nearest_param_name(name)));
                continue;
            }
            auto value = convert(*d, node);
            if (value) {
                if (auto ok = validate(*d, *value); !ok) value = ok.error();
            }
            if (!value) {
                problem(line_of(node), make_error(ExitCode::Config, "config: {}:{}: {}", path, line_of(node),
                                                  value.error().message));
                continue;
            }
            config.entries.push_back({d->id, std::move(*value), line_of(node)});
        }
    }
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
