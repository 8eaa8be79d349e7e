#pragma once
// The parameter registry: the declarations of params.def as data (name, kind, default, range, unit,
// help), lookup by name, parsing and range checks with messages people can act on.

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "util/result.hpp"

namespace puddle::params {

enum class ParamId : std::uint16_t {
#define PARAM(id, ...) id,
#define PARAM_ENUM(id, ...) id,
#include "params/params.def"
    count
};
inline constexpr std::size_t param_count = static_cast<std::size_t>(ParamId::count);

enum class ParamKind { Bool, Int, Float, Vec3, Color, Enum, Path };
using ParamValue = std::variant<bool, int, float, glm::vec3, std::string>;

struct ParamDecl {
    ParamId id;
    std::string_view name;  // "rain.drop_count"
    ParamKind kind;
    ParamValue default_value;
    double min = 0, max = 0;
    std::string_view unit;
    std::string_view help;
    std::vector<std::string_view> choices;  // Enum only
    std::string uniform;                    // "u_rain_drop_count": the shader uniform that mirrors it
};

std::span<const ParamDecl> param_decls();
const ParamDecl& decl(ParamId id);
const ParamDecl* find_param(std::string_view name);
// The declared name closest to `name` (edit distance), for "did you mean" hints. Only the first
// hint_name_limit characters of `name` count: no typo is that long, and a hint for a name of any length
// (a 1 MB knob param in a live edit) then costs the same few microseconds on the frame thread.
inline constexpr std::size_t hint_name_limit = 64;
std::string_view nearest_param_name(std::string_view name);

std::string_view kind_name(ParamKind k);
// "1 to 128 drops", "true or false", "one of: intersect, raymarch", "three numbers, each -1000 to 1000".
std::string describe_range(const ParamDecl& d);
std::string format_value(const ParamValue& v);
// Checks kind and range; the error says what is allowed (the caller adds file:line or the flag).
Result<void> validate(const ParamDecl& d, const ParamValue& v);
// A number as a source read it (TOML, --set, a state file: a 64-bit integer or a double), checked against
// the declared kind and range *before* it is narrowed to the stored int or float, so 4294967297 is an
// error naming 4294967297, never 2147483647. Float ranges are compared at float precision, the precision
// the value is kept in. An integer is fine for a float parameter; a double is not for an int one.
Result<ParamValue> number_value(const ParamDecl& d, std::int64_t v);
Result<ParamValue> number_value(const ParamDecl& d, double v);
// "rain.seed = 4294967297 is out of range: allowed an integer from 0 to 2147483647"; `written` is the
// value as the source wrote it.
Error out_of_range(const ParamDecl& d, std::string_view written);
// Parses a command-line value ("12", "0.5", "true", "0.1,0.2,0.3", "raymarch") and validates it.
Result<ParamValue> parse_value(const ParamDecl& d, std::string_view text);

}  // namespace puddle::params
