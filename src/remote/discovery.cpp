#include "remote/discovery.hpp"

#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "remote/health.hpp"
#include "remote/state_json.hpp"

namespace puddle::remote {

using nlohmann::json;
using params::ParamKind;

namespace {

std::string object_id(std::string_view name) {
    std::string out(name);
    for (char& c : out)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return out;
}

// An entity id's part after the domain, as Home Assistant allows it: lower-case letters, digits and single
// '_' between them ("puddle-Lobby.2" -> "puddle_lobby_2").
std::string entity_slug(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 0x80) {
            out += static_cast<char>(std::tolower(u));
        } else if (!out.empty() && out.back() != '_') {
            out += '_';
        }
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out.empty() ? "puddle" : out;
}

// A step Home Assistant's slider can use: a power of ten near a hundredth of the range, at least 0.001.
double float_step(const params::ParamDecl& d) {
    const double span = d.max - d.min;
    if (span <= 0) return 0.001;
    return std::max(0.001, std::pow(10.0, std::floor(std::log10(span / 100.0))));
}

const char* parameter_component(ParamKind kind) {
    switch (kind) {
        case ParamKind::Int:
        case ParamKind::Float:
            return "number";
        case ParamKind::Bool:
            return "switch";
        case ParamKind::Enum:
            return "select";
        case ParamKind::Vec3:
        case ParamKind::Color:
        case ParamKind::Path:
            break;
    }
    return "text";
}

struct Builder {
    const RemoteSettings& s;
    std::string node;
    json device;
    std::vector<Outbound> out;

    // `component`: Home Assistant's domain (number, select...); `name`: what people read, after the
    // device's name ("Puddle lobby" + "Rain drop count").
    json entity(const char* component, const std::string& object, const std::string& name) const {
        const std::string slug = entity_slug(node + "_" + object);
        return {{"name", name},
                {"unique_id", node + "_" + object},
                // Home Assistant before 2025.10 reads object_id; later ones default_entity_id (and drop
                // object_id in 2026.4): both, naming the same entity id.
                {"object_id", slug},
                {"default_entity_id", fmt::format("{}.{}", component, slug)},
                {"availability_topic", s.prefix + "/availability"},
                {"device", device}};
    }
    void add(const char* component, const std::string& object, const json& config) {
        out.push_back({fmt::format("{}/{}/{}/{}/config", discovery_root, component, node, object),
                       dump_json(config), true});
    }

    void parameter(const params::ParamDecl& d) {
        const std::string object = object_id(d.name);
        json c = entity(parameter_component(d.kind), object, readable_name(d.name));
        c["command_topic"] = fmt::format("{}/set/{}", s.prefix, d.name);
        c["state_topic"] = fmt::format("{}/state/{}", s.prefix, d.name);
        switch (d.kind) {
            case ParamKind::Int:
            case ParamKind::Float:
                c["min"] = d.min;
                c["max"] = d.max;
                c["step"] = d.kind == ParamKind::Int ? 1.0 : float_step(d);
                if (!d.unit.empty()) c["unit_of_measurement"] = d.unit;
                c["mode"] = "box";
                break;
            case ParamKind::Bool:
                c["payload_on"] = c["state_on"] = "true";
                c["payload_off"] = c["state_off"] = "false";
                break;
            case ParamKind::Enum:
                c["options"] = d.choices;
                break;
            case ParamKind::Vec3:
            case ParamKind::Color:
            case ParamKind::Path:
                c["max"] = 255;
                break;
        }
        add(parameter_component(d.kind), object, c);
    }
};

Builder build(const RemoteSettings& s, const std::vector<std::string>& presets, std::string_view version,
              HealthSensors sensors) {
    Builder b{s, node_id(s), {}, {}};
    b.device = {{"identifiers", json::array({b.node})},
                {"name", device_name(s)},
                {"manufacturer", "Puddle"},
                {"model", "Puddle rain display"},
                {"sw_version", version}};
    for (const params::ParamDecl& d : params::param_decls())
        if (s.writable.allows(d)) b.parameter(d);

    json preset = b.entity("select", "preset", "Preset");
    std::vector<std::string> options{"none"};
    options.insert(options.end(), presets.begin(), presets.end());
    preset["options"] = options;
    preset["command_topic"] = s.prefix + "/preset/set";
    preset["state_topic"] = s.prefix + "/preset";
    b.add("select", "preset", preset);

    for (const char* command : command_names) {
        const std::string object = object_id(command);
        json c = b.entity("button", object, readable_name(command));
        c["command_topic"] = s.prefix + "/command";
        c["payload_press"] = command;
        b.add("button", object, c);
    }
    for (const HealthField& f : health_fields) {
        if (std::string_view(f.key) == "soc_temperature_c" && !sensors.soc_temperature) continue;
        json c = b.entity("sensor", f.key, f.name);
        c["state_topic"] = s.prefix + "/health";
        c["value_template"] = fmt::format("{{{{ value_json.{} }}}}", f.key);
        c["entity_category"] = "diagnostic";
        c["state_class"] = "measurement";
        if (*f.unit) c["unit_of_measurement"] = f.unit;
        if (*f.device_class) c["device_class"] = f.device_class;
        b.add("sensor", f.key, c);
    }
    if (sensors.board_power)
        for (const HealthField& f : health_problem_fields) {
            json c = b.entity("binary_sensor", f.key, f.name);
            c["state_topic"] = s.prefix + "/health";
            c["value_template"] = fmt::format("{{{{ 'ON' if value_json.{} else 'OFF' }}}}", f.key);
            c["entity_category"] = "diagnostic";
            c["device_class"] = f.device_class;
            b.add("binary_sensor", f.key, c);
        }
    json image = b.entity("image", "screenshot", "Screenshot");
    image["image_topic"] = s.prefix + "/screenshot";
    image["content_type"] = "image/jpeg";
    b.add("image", "screenshot", image);
    return b;
}

}  // namespace

std::string node_id(const RemoteSettings& s) {
    return object_id(s.client_id);
}

std::string readable_name(std::string_view key) {
    std::string out(key);
    for (char& c : out)
        if (c == '.' || c == '_' || c == '-') c = ' ';
    if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
    return out;
}

std::string device_name(const RemoteSettings& s) {
    return "Puddle " + (s.screen_name.empty() ? s.client_id : s.screen_name);
}

std::vector<Outbound> discovery_configs(const RemoteSettings& s, const std::vector<std::string>& presets,
                                        std::string_view version, HealthSensors sensors) {
    return std::move(build(s, presets, version, sensors).out);
}

std::vector<Outbound> clear_discovery(const RemoteSettings& s, const std::vector<std::string>& presets,
                                      std::string_view version) {
    std::vector<Outbound> out =
        discovery_configs(s, presets, version, {.soc_temperature = true, .board_power = true});
    for (Outbound& o : out) o.payload.clear();
    return out;
}

}  // namespace puddle::remote
