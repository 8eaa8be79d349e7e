#include "params/toml_value.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <sstream>

#include "util/safe_quote.hpp"

namespace puddle::params {

int toml_line(const toml::node& n) {
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
Result<ParamValue> toml_param_value(const ParamDecl& d, const toml::node& n) {
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

}  // namespace puddle::params
