#include "params/registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "util/safe_quote.hpp"

namespace puddle::params {

const ParamDecl& decl(ParamId id) {
    return param_decls()[static_cast<std::size_t>(id)];
}

const ParamDecl* find_param(std::string_view name) {
    for (const ParamDecl& d : param_decls())
        if (d.name == name) return &d;
    return nullptr;
}

namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string number(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e15) return fmt::format("{}", static_cast<long long>(v));
    return fmt::format("{:g}", v);
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// std::errc() when all of `s` is one number; result_out_of_range when it is a number too large for T;
// invalid_argument otherwise.
template <class T>
std::errc parse_number(std::string_view s, T& out) {
    s = trim(s);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    const char* end = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(s.data(), end, out);
    if (s.empty() || ptr != end) return std::errc::invalid_argument;
    return ec;
}

Error range_error(const ParamDecl& d, const ParamValue& v) {
    return out_of_range(d, format_value(v));
}

Error wrong_type(const ParamDecl& d, std::string_view written) {
    return make_error(ExitCode::Config, "{} = {} has the wrong type: expected {}", d.name, written,
                      describe_range(d));
}

// Whether `v` is inside the declared range once stored as a float: a finite float, compared at float
// precision (6.2831853 is stored as 6.28318548, and that must read back in range).
bool float_in_range(const ParamDecl& d, double v) {
    const auto f = static_cast<float>(v);
    return std::isfinite(v) && std::isfinite(f) && f >= static_cast<float>(d.min) &&
           f <= static_cast<float>(d.max);
}

}  // namespace

Error out_of_range(const ParamDecl& d, std::string_view written) {
    return make_error(ExitCode::Config, "{} = {} is out of range: allowed {}", d.name, written,
                      describe_range(d));
}

Result<ParamValue> number_value(const ParamDecl& d, std::int64_t v) {
    switch (d.kind) {
        case ParamKind::Int:
            // Both checks, so that an int64 that passes converts exactly whatever the declared range.
            if (static_cast<double>(v) < d.min || static_cast<double>(v) > d.max ||
                v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
                return out_of_range(d, fmt::format("{}", v));
            return ParamValue(static_cast<int>(v));
        case ParamKind::Float:
            if (!float_in_range(d, static_cast<double>(v))) return out_of_range(d, fmt::format("{}", v));
            return ParamValue(static_cast<float>(v));
        default:
            return wrong_type(d, fmt::format("{}", v));
    }
}

Result<ParamValue> number_value(const ParamDecl& d, double v) {
    if (d.kind != ParamKind::Float) return wrong_type(d, fmt::format("{}", v));
    if (!float_in_range(d, v)) return out_of_range(d, fmt::format("{}", v));
    return ParamValue(static_cast<float>(v));
}

std::string_view nearest_param_name(std::string_view name) {
    name = name.substr(0, hint_name_limit);  // edit distance is quadratic: found by the state fuzzer
    std::string_view best;
    std::size_t best_d = SIZE_MAX;
    for (const ParamDecl& d : param_decls()) {
        // Compare with the full name and with the key alone, so "drop_cont" finds "rain.drop_count".
        const std::string_view key = d.name.substr(d.name.find('.') + 1);
        const std::size_t dist = std::min(edit_distance(name, d.name), edit_distance(name, key) + 1);
        if (dist < best_d) best_d = dist, best = d.name;
    }
    return best;
}

std::string_view kind_name(ParamKind k) {
    switch (k) {
        case ParamKind::Bool:
            return "bool";
        case ParamKind::Int:
            return "int";
        case ParamKind::Float:
            return "float";
        case ParamKind::Vec3:
            return "vec3";
        case ParamKind::Color:
            return "color";
        case ParamKind::Enum:
            return "enum";
        case ParamKind::Path:
            return "text";
    }
    return "?";
}

std::string describe_range(const ParamDecl& d) {
    const std::string unit = d.unit.empty() ? "" : fmt::format(" {}", d.unit);
    switch (d.kind) {
        case ParamKind::Bool:
            return "true or false";
        case ParamKind::Int:
            return fmt::format("an integer from {} to {}{}", number(d.min), number(d.max), unit);
        case ParamKind::Float:
            return fmt::format("a number from {} to {}{}", number(d.min), number(d.max), unit);
        case ParamKind::Vec3:
        case ParamKind::Color:
            return fmt::format("three numbers [x, y, z], each from {} to {}{}", number(d.min), number(d.max),
                               unit);
        case ParamKind::Enum:
            return fmt::format("one of: {}", fmt::join(d.choices, ", "));
        case ParamKind::Path:
            return fmt::format("text ({})", d.unit);
    }
    return "";
}

std::string format_value(const ParamValue& v) {
    struct Visitor {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(int i) const { return fmt::format("{}", i); }
        // The shortest text that reads back as the same float: the state file keeps knob values exactly.
        std::string operator()(float f) const { return fmt::format("{}", f); }
        std::string operator()(const glm::vec3& c) const {
            return fmt::format("[{}, {}, {}]", c.x, c.y, c.z);
        }
        std::string operator()(const std::string& s) const { return fmt::format("\"{}\"", s); }
    };
    return std::visit(Visitor{}, v);
}

Result<void> validate(const ParamDecl& d, const ParamValue& v) {
    auto wrong_kind = [&] { return wrong_type(d, format_value(v)); };
    switch (d.kind) {
        case ParamKind::Bool:
            if (!std::holds_alternative<bool>(v)) return wrong_kind();
            return {};
        case ParamKind::Int: {
            if (!std::holds_alternative<int>(v)) return wrong_kind();
            const int i = std::get<int>(v);
            if (i < d.min || i > d.max) return range_error(d, v);
            return {};
        }
        case ParamKind::Float: {
            if (!std::holds_alternative<float>(v)) return wrong_kind();
            if (!float_in_range(d, static_cast<double>(std::get<float>(v)))) return range_error(d, v);
            return {};
        }
        case ParamKind::Vec3:
        case ParamKind::Color: {
            if (!std::holds_alternative<glm::vec3>(v)) return wrong_kind();
            const glm::vec3 c = std::get<glm::vec3>(v);
            for (int i = 0; i < 3; ++i)
                if (!float_in_range(d, static_cast<double>(c[i]))) return range_error(d, v);
            return {};
        }
        case ParamKind::Enum: {
            if (!std::holds_alternative<std::string>(v)) return wrong_kind();
            const auto& s = std::get<std::string>(v);
            if (std::find(d.choices.begin(), d.choices.end(), s) == d.choices.end())
                return make_error(ExitCode::Config, "{} = \"{}\" is not allowed: {}", d.name, safe_quote(s),
                                  describe_range(d));
            return {};
        }
        case ParamKind::Path:
            if (!std::holds_alternative<std::string>(v)) return wrong_kind();
            return {};
    }
    return {};
}

Result<ParamValue> parse_value(const ParamDecl& d, std::string_view text) {
    const std::string_view s = trim(text);
    ParamValue v;
    bool ok = true;
    switch (d.kind) {
        case ParamKind::Bool:
            if (s == "true" || s == "1" || s == "on" || s == "yes")
                v = true;
            else if (s == "false" || s == "0" || s == "off" || s == "no")
                v = false;
            else
                ok = false;
            break;
        case ParamKind::Int: {
            std::int64_t i = 0;
            if (const auto ec = parse_number(s, i); ec == std::errc::result_out_of_range)
                return out_of_range(d, s);
            else if (ec != std::errc())
                ok = false;
            else
                return number_value(d, i);
            break;
        }
        case ParamKind::Float: {
            double f = 0;
            if (const auto ec = parse_number(s, f); ec == std::errc::result_out_of_range)
                return out_of_range(d, s);
            else if (ec != std::errc())
                ok = false;
            else
                return number_value(d, f);
            break;
        }
        case ParamKind::Vec3:
        case ParamKind::Color: {
            std::string_view rest = s;
            if (rest.starts_with('[') && rest.ends_with(']')) rest = rest.substr(1, rest.size() - 2);
            double c[3] = {};
            for (int i = 0; i < 3 && ok; ++i) {
                const auto comma = rest.find(',');
                if ((i < 2) == (comma == std::string_view::npos))
                    ok = false;
                else if (const auto ec = parse_number(rest.substr(0, comma), c[i]);
                         ec == std::errc::result_out_of_range)
                    return out_of_range(d, s);
                else
                    ok = ec == std::errc();
                rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
            }
            // 1e39 does not fit a float: out of range as written, not infinity (validate checks the rest).
            for (double x : c)
                if (ok && !std::isfinite(static_cast<float>(x))) return out_of_range(d, s);
            v = glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
            break;
        }
        case ParamKind::Enum:
        case ParamKind::Path:
            v = std::string(s);
            break;
    }
    if (!ok)
        return make_error(ExitCode::Config, "{} = \"{}\" is not valid: expected {}", d.name, safe_quote(s),
                          describe_range(d));
    if (auto r = validate(d, v); !r) return r.error();
    return v;
}

}  // namespace puddle::params
