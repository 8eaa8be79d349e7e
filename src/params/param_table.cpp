// Builds the registry's table from params.def: the one place declarations become data.
#include <glm/vec3.hpp>

#include "params/registry.hpp"

namespace puddle::params {

namespace {

std::vector<std::string_view> split_choices(std::string_view s) {
    std::vector<std::string_view> out;
    while (!s.empty()) {
        const auto bar = s.find('|');
        out.push_back(s.substr(0, bar));
        if (bar == std::string_view::npos) break;
        s.remove_prefix(bar + 1);
    }
    return out;
}

std::string uniform_name(std::string_view name) {
    std::string u = "u_";
    for (char c : name) u += c == '.' ? '_' : c;
    return u;
}

std::vector<ParamDecl> build_table() {
    std::vector<ParamDecl> t;
#define PARAM(id, name, kind, def, lo, hi, unit, help) \
    t.push_back({ParamId::id, name, ParamKind::kind, ParamValue(def), lo, hi, unit, help, {}, uniform_name(name)});
#define PARAM_ENUM(id, name, def, choices, help)                                                        \
    t.push_back({ParamId::id, name, ParamKind::Enum, ParamValue(std::string(def)), 0, 0, "", help,       \
                 split_choices(choices), uniform_name(name)});
#include "params/params.def"
    return t;
}

}  // namespace

std::span<const ParamDecl> param_decls() {
    static const std::vector<ParamDecl> table = build_table();
    return table;
}

}  // namespace puddle::params
