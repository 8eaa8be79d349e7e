// Builds the registry's table from params.def: the one place declarations become data.
#include <glm/vec3.hpp>

#include "params/param_types.hpp"
#include "params/registry.hpp"

namespace puddle::params {

namespace {

std::string uniform_name(std::string_view name) {
    std::string u = "u_";
    for (char c : name) u += c == '.' ? '_' : c;
    return u;
}

template <class E>
std::vector<std::string_view> choices_of() {
    constexpr auto names = choice_names<E>();  // views of string literals: they live as long as the program
    return {names.begin(), names.end()};
}

std::vector<ParamDecl> build_table() {
    std::vector<ParamDecl> t;
#define PARAM(id, name, kind, def, lo, hi, unit, help) \
    t.push_back(                                       \
        {ParamId::id, name, ParamKind::kind, ParamValue(def), lo, hi, unit, help, {}, uniform_name(name)});
#define PARAM_ENUM(id, name, Type, def, CHOICES, help)                                                      \
    t.push_back({ParamId::id, name, ParamKind::Enum, ParamValue(std::string(choice_name(Type::def))), 0, 0, \
                 "", help, choices_of<Type>(), uniform_name(name)});
#include "params/params.def"
    return t;
}

}  // namespace

std::span<const ParamDecl> param_decls() {
    static const std::vector<ParamDecl> table = build_table();
    return table;
}

}  // namespace puddle::params
