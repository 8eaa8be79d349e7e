#pragma once
// The C++ side of params.def: one enum per enumerated parameter, and each parameter's value type, so
// that Params::get<ParamId::x>() returns an int, a float, a SceneKind... and a wrong kind or an unknown
// choice is a compile error, not a throw in the frame loop.

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include "params/registry.hpp"

namespace puddle::params {

// enum class Tonemap : std::uint8_t { clip, soft, reinhard, aces }; ... in params.def's order of choices,
// which is also the index a shader sees.
#define PUDDLE_ENUM_MEMBER(ident, spelling) ident,
#define PARAM(...)
#define PARAM_ENUM(id, name, Type, def, CHOICES, help) \
    enum class Type : std::uint8_t { CHOICES(PUDDLE_ENUM_MEMBER) };
#include "params/params.def"
#undef PUDDLE_ENUM_MEMBER

// The number of choices of an enum, and their spellings in the config (choice_names<Tonemap>()[0] is "clip").
template <class E>
inline constexpr std::size_t choice_count = 0;
template <class E>
constexpr std::array<std::string_view, choice_count<E>> choice_names();
#define PUDDLE_ENUM_COUNT(ident, spelling) +1
#define PUDDLE_ENUM_SPELLING(ident, spelling) std::string_view(spelling),
#define PARAM(...)
#define PARAM_ENUM(id, name, Type, def, CHOICES, help)                                \
    template <>                                                                       \
    inline constexpr std::size_t choice_count<Type> = 0 CHOICES(PUDDLE_ENUM_COUNT);   \
    template <>                                                                       \
    constexpr std::array<std::string_view, choice_count<Type>> choice_names<Type>() { \
        return {CHOICES(PUDDLE_ENUM_SPELLING)};                                       \
    }
#include "params/params.def"
#undef PUDDLE_ENUM_COUNT
#undef PUDDLE_ENUM_SPELLING

template <class E>
constexpr std::string_view choice_name(E e) {
    return choice_names<E>()[static_cast<std::size_t>(e)];
}

namespace detail {
template <ParamKind>
struct KindType;
template <>
struct KindType<ParamKind::Bool> {
    using type = bool;
};
template <>
struct KindType<ParamKind::Int> {
    using type = int;
};
template <>
struct KindType<ParamKind::Float> {
    using type = float;
};
template <>
struct KindType<ParamKind::Vec3> {
    using type = glm::vec3;
};
template <>
struct KindType<ParamKind::Color> {
    using type = glm::vec3;
};
template <>
struct KindType<ParamKind::Path> {
    using type = std::string;
};
}  // namespace detail

// ParamType<ParamId::rain_drop_count> is int; ParamType<ParamId::scene_kind> is SceneKind.
template <ParamId id>
struct ParamTraits;
#define PARAM(id, name, kind, ...)                            \
    template <>                                               \
    struct ParamTraits<ParamId::id> {                         \
        using type = detail::KindType<ParamKind::kind>::type; \
    };
#define PARAM_ENUM(id, name, Type, ...) \
    template <>                         \
    struct ParamTraits<ParamId::id> {   \
        using type = Type;              \
    };
#include "params/params.def"
template <ParamId id>
using ParamType = typename ParamTraits<id>::type;

}  // namespace puddle::params
