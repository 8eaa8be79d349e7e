#include "remote/discovery.hpp"

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

// A step Home Assistant's slider can use: a power of ten near a hundredth of the range, at least 0.001.
double float_step(const params::ParamDecl& d) {
    const double span = d.max - d.min;
    if (span <= 0) return 0.001;
    return std::max(0.001, std::pow(10.0, std::floor(std::log10(span / 100.0))));
}

struct Builder {
    const RemoteSettings& s;
    std::string node;
    json device;
    std::vector<Outbound> out;

    json entity(const std::string& object, const std::string& name) const {
        return {{"name", name},
                {"unique_id", node + "_" + object},
                {"object_id", node + "_" + object},
                {"availability_topic", s.prefix + "/availability"},
                {"device", device}};
    }
    void add(const char* component, const std::string& object, const json& config) {
        out.push_back({fmt::format("{}/{}/{}/{}/config", discovery_root, component, node, object),
                       dump_json(config), true});
    }

    void parameter(const params::ParamDecl& d) {
        const std::string object = object_id(d.name);
        json c = entity(object, std::string(d.name));
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
                return add("number", object, c);
            case ParamKind::Bool:
                c["payload_on"] = c["state_on"] = "true";
                c["payload_off"] = c["state_off"] = "false";
                return add("switch", object, c);
            case ParamKind::Enum:
                c["options"] = d.choices;
                return add("select", object, c);
            case ParamKind::Vec3:
            case ParamKind::Color:
            case ParamKind::Path:
                c["max"] = 255;
                return add("text", object, c);
        }
    }
};

Builder build(const RemoteSettings& s, const std::vector<std::string>& presets, std::string_view version,
              HealthSensors sensors) {
    Builder b{s, node_id(s), {}, {}};
    b.device = {{"identifiers", json::array({b.node})},
                {"name", "Puddle " + s.client_id},
                {"manufacturer", "Puddle"},
                {"model", "Puddle rain display"},
                {"sw_version", version}};
    for (const params::ParamDecl& d : params::param_decls())
        if (s.writable.allows(d)) b.parameter(d);

    json preset = b.entity("preset", "Preset");
    std::vector<std::string> options{"none"};
    options.insert(options.end(), presets.begin(), presets.end());
    preset["options"] = options;
    preset["command_topic"] = s.prefix + "/preset/set";
    preset["state_topic"] = s.prefix + "/preset";
    b.add("select", "preset", preset);

    for (const char* command : command_names) {
        const std::string object = object_id(command);
        json c = b.entity(object, command);
        c["command_topic"] = s.prefix + "/command";
        c["payload_press"] = command;
        b.add("button", object, c);
    }
    for (const HealthField& f : health_fields) {
        if (std::string_view(f.key) == "soc_temperature_c" && !sensors.soc_temperature) continue;
        json c = b.entity(f.key, f.name);
        c["state_topic"] = s.prefix + "/health";
        c["value_template"] = fmt::format("{{{{ value_json.{} }}}}", f.key);
        c["entity_category"] = "diagnostic";
        c["state_class"] = "measurement";
        if (*f.unit) c["unit_of_measurement"] = f.unit;
        if (*f.device_class) c["device_class"] = f.device_class;
        b.add("sensor", f.key, c);
    }
    json image = b.entity("screenshot", "Screenshot");
    image["image_topic"] = s.prefix + "/screenshot";
    image["content_type"] = "image/jpeg";
    b.add("image", "screenshot", image);
    return b;
}

}  // namespace

std::string node_id(const RemoteSettings& s) {
    return object_id(s.client_id);
}

std::vector<Outbound> discovery_configs(const RemoteSettings& s, const std::vector<std::string>& presets,
                                        std::string_view version, HealthSensors sensors) {
    return std::move(build(s, presets, version, sensors).out);
}

std::vector<Outbound> clear_discovery(const RemoteSettings& s, const std::vector<std::string>& presets,
                                      std::string_view version) {
    std::vector<Outbound> out = discovery_configs(s, presets, version, {.soc_temperature = true});
    for (Outbound& o : out) o.payload.clear();
    return out;
}

}  // namespace puddle::remote
