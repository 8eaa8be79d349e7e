#include "params/config_loader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "params/knob_spec_parse.hpp"

namespace puddle::params {

namespace {

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

// Converts a TOML node to the declared kind; returns nullopt when the TOML type cannot be that kind.
std::optional<ParamValue> convert(const ParamDecl& d, const toml::node& n) {
    switch (d.kind) {
        case ParamKind::Bool:
            if (auto b = n.value_exact<bool>()) return ParamValue(*b);
            return std::nullopt;
        case ParamKind::Int:
            if (auto i = n.value_exact<int64_t>()) {
                if (*i < INT32_MIN || *i > INT32_MAX) return ParamValue(static_cast<int>(*i > 0 ? INT32_MAX : INT32_MIN));
                return ParamValue(static_cast<int>(*i));
            }
            return std::nullopt;
        case ParamKind::Float:
            if (auto f = n.value<double>()) return ParamValue(static_cast<float>(*f));  // ints are fine too
            return std::nullopt;
        case ParamKind::Vec3:
        case ParamKind::Color: {
            const toml::array* a = n.as_array();
            if (!a || a->size() != 3) return std::nullopt;
            glm::vec3 c{};
            for (std::size_t i = 0; i < 3; ++i) {
                auto f = (*a)[i].value<double>();
                if (!f) return std::nullopt;
                c[static_cast<int>(i)] = static_cast<float>(*f);
            }
            return ParamValue(c);
        }
        case ParamKind::Enum:
            if (auto s = n.value_exact<std::string>()) return ParamValue(*s);
            return std::nullopt;
        case ParamKind::Path:
            if (auto s = n.value_exact<std::string>()) return ParamValue(*s);
            // Six cubemap faces may be given as an array of paths; they travel joined by '|'.
            if (const toml::array* a = n.as_array(); a && !a->empty()) {
                std::string joined;
                for (const toml::node& e : *a) {
                    auto s = e.value_exact<std::string>();
                    if (!s) return std::nullopt;
                    joined += (joined.empty() ? "" : "|") + *s;
                }
                return ParamValue(joined);
            }
            return std::nullopt;
    }
    return std::nullopt;
}

std::string toml_text(const toml::node& n) {
    std::ostringstream out;
    n.visit([&](auto&& v) { out << v; });
    return out.str();
}

}  // namespace

Result<Config> parse_config(std::string_view text, std::string_view path) {
    Config config{std::string(path), {}};
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        return make_error(ExitCode::Config, "config: {}:{}: {}", path, e.source().begin.line, e.description());
    }
    // toml++ visits keys in name order; report the problem nearest the top of the file, as people read it.
    std::optional<std::pair<int, Error>> first_problem;
    auto problem = [&](int line, Error e) {
        if (!first_problem || line < first_problem->first) first_problem.emplace(line, std::move(e));
    };
    for (auto&& [section_key, section_node] : root) {
        if (section_key.str() == "preset") {
            auto name = section_node.value_exact<std::string>();
            if (!name || name->empty())
                problem(line_of(section_node), make_error(ExitCode::Config, "config: {}:{}: preset must be a preset's name, e.g. preset = \"downpour\"",
                                                          path, line_of(section_node)));
            else
                config.preset = *name, config.preset_line = line_of(section_node);
            continue;
        }
        if (section_key.str() == "knob") {
            const toml::array* knobs = section_node.as_array();
            if (!knobs || !knobs->is_array_of_tables()) {
                problem(line_of(section_node), make_error(ExitCode::Config, "config: {}:{}: knobs are written as [[knob]] tables",
                                                          path, line_of(section_node)));
                continue;
            }
            int index = 0;
            for (const toml::node& k : *knobs) {
                auto knob = parse_knob(*k.as_table(), path, ++index);
                if (!knob) problem(line_of(k), knob.error());
                else config.knobs.push_back(std::move(*knob));
            }
            continue;
        }
        const toml::table* section = section_node.as_table();
        if (!section) {
            const std::string key(section_key.str());
            problem(line_of(section_node),
                    make_error(ExitCode::Config, "config: {}:{}: '{}' must be inside a [section] (did you mean '{}'?)",
                               path, line_of(section_node), key, nearest_param_name(key)));
            continue;
        }
        for (auto&& [key, node] : *section) {
            const std::string name = fmt::format("{}.{}", section_key.str(), key.str());
            const ParamDecl* d = find_param(name);
            if (!d) {
                problem(line_of(node), make_error(ExitCode::Config, "config: {}:{}: unknown key '{}' (did you mean '{}'?)",
                                                  path, line_of(node), name, nearest_param_name(name)));
                continue;
            }
            auto value = convert(*d, node);
            if (!value) {
                problem(line_of(node),
                        make_error(ExitCode::Config, "config: {}:{}: {} = {} has the wrong type: expected {}", path,
                                   line_of(node), name, toml_text(node), describe_range(*d)));
                continue;
            }
            if (auto ok = validate(*d, *value); !ok) {
                problem(line_of(node),
                        make_error(ExitCode::Config, "config: {}:{}: {}", path, line_of(node), ok.error().message));
                continue;
            }
            config.entries.push_back({d->id, std::move(*value), line_of(node)});
        }
    }
    if (first_problem) return first_problem->second;
    std::sort(config.entries.begin(), config.entries.end(),
              [](const ConfigEntry& a, const ConfigEntry& b) { return a.line < b.line; });
    return config;
}

Result<Config> load_config_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ExitCode::Config, "config: {}: cannot open: {}", path, std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    return parse_config(text.str(), path);
}

void apply_config(const Config& config, Params& params, ParamSource source) {
    for (const ConfigEntry& e : config.entries) params.set(e.id, e.value, source);
}

Result<ConfigEntry> parse_assignment(std::string_view assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos)
        return make_error(ExitCode::Config, "--set {}: expected name=value, e.g. --set rain.drop_count=20", assignment);
    const std::string_view name = assignment.substr(0, eq);
    const ParamDecl* d = find_param(name);
    if (!d)
        return make_error(ExitCode::Config, "--set {}: unknown parameter '{}' (did you mean '{}'?)", assignment, name,
                          nearest_param_name(name));
    auto value = parse_value(*d, assignment.substr(eq + 1));
    if (!value) return make_error(ExitCode::Config, "--set: {}", value.error().message);
    return ConfigEntry{d->id, std::move(value).value(), 0};
}

}  // namespace puddle::params
