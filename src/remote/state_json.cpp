#include "remote/state_json.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace puddle::remote {

namespace {

nlohmann::json json_value(const params::ParamValue& v) {
    struct Visitor {
        nlohmann::json operator()(bool b) const { return b; }
        nlohmann::json operator()(int i) const { return i; }
        // The shortest text that reads back as the same float, as a JSON number (0.3, not 0.30000001192).
        nlohmann::json operator()(float f) const { return nlohmann::json::parse(fmt::format("{}", f)); }
        nlohmann::json operator()(const glm::vec3& c) const {
            return nlohmann::json::array({(*this)(c.x), (*this)(c.y), (*this)(c.z)});
        }
        nlohmann::json operator()(const std::string& s) const { return s; }
    };
    return std::visit(Visitor{}, v);
}

}  // namespace

std::string state_document(const params::Params& params) {
    nlohmann::json doc = nlohmann::json::object();
    for (const params::ParamDecl& d : params::param_decls())
        doc[std::string(d.name)] = json_value(params.at(d.id));
    return dump_json(doc);
}

std::string set_syntax(const params::ParamValue& value) {
    if (const auto* s = std::get_if<std::string>(&value)) return *s;
    if (const auto* c = std::get_if<glm::vec3>(&value)) return fmt::format("{},{},{}", c->x, c->y, c->z);
    return params::format_value(value);
}

std::string error_document(const std::string& topic, const std::string& message) {
    return dump_json(nlohmann::json{{"topic", topic}, {"error", message}});
}

std::string dump_json(const nlohmann::json& doc) {
    return doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace puddle::remote
