#include "params/knob_spec_parse.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <sstream>

#include "util/safe_quote.hpp"

namespace puddle::params {

namespace {

constexpr std::array known_keys{"kind", "chip",         "line",   "a",          "b",    "param",
                                "step", "acceleration", "action", "active_low", "bias", "debounce_ms"};

int line_of(const toml::node& n) {
    return static_cast<int>(n.source().begin.line);
}

std::string as_written(const toml::node& n) {
    std::ostringstream out;
    n.visit([&](auto&& v) { out << v; });
    return out.str();
}

constexpr int max_line_offset = 4095;
constexpr std::size_t max_line_name_bytes = 64;  // the kernel's GPIO_MAX_NAME_SIZE is 32

// A line is an offset (17, or "17") or a line name ("GPIO17"); an offset is checked as written, before
// anything narrows it.
std::optional<std::string> line_ref(const toml::node& n) {
    if (auto i = n.value_exact<int64_t>(); i && *i >= 0 && *i <= max_line_offset) return std::to_string(*i);
    auto s = n.value_exact<std::string>();
    if (!s || s->empty() || s->size() > max_line_name_bytes) return std::nullopt;
    if (s->find_first_not_of("0123456789") == std::string::npos &&
        (s->size() > 4 || std::stoi(*s) > max_line_offset))
        return std::nullopt;
    return *s;
}

template <typename E, std::size_t N>
std::optional<E> pick(std::string_view text, const std::array<E, N>& values, std::string_view (*name)(E)) {
    for (E v : values)
        if (name(v) == text) return v;
    return std::nullopt;
}

}  // namespace

Result<KnobSpec> parse_knob(const toml::table& table, std::string_view path, int index) {
    KnobSpec k;
    k.config_line = line_of(table);
    const int at = k.config_line;
    auto fail = [&](int line, std::string what) {
        return make_error(ExitCode::Config, "config: {}:{}: knob {}: {}", path, line ? line : at, index,
                          what);
    };
    for (auto&& [key, node] : table) {
        bool known = false;
        for (const char* name : known_keys) known = known || key.str() == name;
        if (!known)
            return fail(line_of(node), fmt::format("unknown key '{}' (knob keys: {})", safe_quote(key.str()),
                                                   fmt::join(known_keys, ", ")));
    }

    const auto kind_text = table["kind"].value_exact<std::string>();
    constexpr std::array kinds{KnobKind::Encoder, KnobKind::Button, KnobKind::Switch};
    const auto kind = kind_text ? pick(*kind_text, kinds, knob_kind_name) : std::nullopt;
    if (!kind) return fail(0, "kind must be \"encoder\", \"button\" or \"switch\"");
    k.kind = *kind;

    if (auto n = table.get("chip")) {
        auto s = n->value_exact<std::string>();
        if (!s || s->empty())
            return fail(line_of(*n), "chip must be text: a name (\"gpiochip0\"), a path or a label");
        k.chip = *s;
    }
    auto read_line = [&](const char* key, std::string& out) -> Result<void> {
        const toml::node* n = table.get(key);
        if (!n)
            return fail(0,
                        fmt::format("'{}' is missing: the line offset (17) or line name (\"GPIO17\")", key));
        auto ref = line_ref(*n);
        if (!ref)
            return fail(line_of(*n),
                        fmt::format("{} must be a line offset (0 to {}) or a line name (at most {} bytes)",
                                    key, max_line_offset, max_line_name_bytes));
        out = *ref;
        return {};
    };
    if (k.kind == KnobKind::Encoder) {
        if (auto r = read_line("a", k.line); !r) return r.error();
        if (auto r = read_line("b", k.line_b); !r) return r.error();
        // Quadrature needs two lines: one line twice never shows a turn.
        if (k.line == k.line_b)
            return fail(
                line_of(*table.get("b")),
                fmt::format("a and b are both line {}: an encoder needs two lines", safe_quote(k.line)));
    } else {
        if (auto r = read_line("line", k.line); !r) return r.error();
    }

    if (auto n = table.get("active_low")) {
        auto b = n->value_exact<bool>();
        if (!b) return fail(line_of(*n), "active_low must be true or false");
        k.active_low = *b;
    }
    if (auto n = table.get("bias")) {
        constexpr std::array biases{LineBias::AsIs, LineBias::PullUp, LineBias::PullDown, LineBias::Disabled};
        auto s = n->value_exact<std::string>();
        auto b = s ? pick(*s, biases, bias_name) : std::nullopt;
        if (!b)
            return fail(line_of(*n), "bias must be \"pull-up\", \"pull-down\", \"disabled\" or \"as-is\"");
        k.bias = *b;
    }
    if (auto n = table.get("param")) {
        auto s = n->value_exact<std::string>();
        const ParamDecl* d = s ? find_param(*s) : nullptr;
        if (!d)
            return fail(line_of(*n),
                        fmt::format("param '{}' is not a parameter (did you mean '{}'?)",
                                    safe_quote(s.value_or("")), nearest_param_name(s.value_or(""))));
        k.param = d->id;
    }
    if (auto n = table.get("action")) {
        constexpr std::array actions{ButtonAction::NextPreset, ButtonAction::PreviousPreset,
                                     ButtonAction::Reset, ButtonAction::Toggle, ButtonAction::SaveState};
        auto s = n->value_exact<std::string>();
        auto a = s ? pick(*s, actions, button_action_name) : std::nullopt;
        if (!a)
            return fail(
                line_of(*n),
                "action must be \"next-preset\", \"previous-preset\", \"reset\", \"toggle\" or \"save\"");
        k.action = *a;
    } else if (k.kind == KnobKind::Button) {
        return fail(0,
                    "a button needs an action: \"next-preset\", \"previous-preset\", \"reset\", \"toggle\" "
                    "or \"save\"");
    }
    // Numbers are checked as written (an int64 or a double) before they are stored; the message names the
    // key, the value and the range.
    auto number = [&](const char* key, double lo, double hi, bool whole, double& out) -> Result<void> {
        const toml::node* n = table.get(key);
        if (!n) return {};
        std::optional<double> v = n->value_exact<double>();
        if (auto i = n->value_exact<int64_t>()) v = static_cast<double>(*i);
        if (!v || (whole && !n->is_integer()) || !(*v >= lo && *v <= hi))
            return fail(line_of(*n),
                        fmt::format("{} = {} is not allowed: {} from {} to {}", key, as_written(*n),
                                    whole ? "a whole number" : "a number", lo, hi));
        out = *v;
        return {};
    };
    if (auto r = number("step", 0, 1e6, false, k.step); !r) return r.error();
    if (auto r = number("acceleration", 0, 100, false, k.acceleration); !r) return r.error();
    double debounce = k.debounce_ms;
    if (auto r = number("debounce_ms", 0, 1000, true, debounce); !r) return r.error();
    k.debounce_ms = static_cast<int>(debounce);  // whole and within 0..1000: exact

    const ParamDecl* target = k.param ? &decl(*k.param) : nullptr;
    const bool numeric = target && (target->kind == ParamKind::Int || target->kind == ParamKind::Float);
    const bool boolean = target && target->kind == ParamKind::Bool;
    switch (k.kind) {
        case KnobKind::Encoder:
            if (!numeric)
                return fail(0, "an encoder needs param = a number parameter (e.g. \"rain.intensity\")");
            if (k.step > target->max - target->min)
                return fail(line_of(*table.get("step")),
                            fmt::format("step = {} is larger than the whole range of {} ({} to {})", k.step,
                                        target->name, target->min, target->max));
            if (target->kind == ParamKind::Int && k.step != std::floor(k.step))
                return fail(line_of(*table.get("step")),
                            fmt::format("step = {} is not a whole number, and {} is an integer", k.step,
                                        target->name));
            if (k.step == 0) k.step = (target->max - target->min) / 50.0;
            if (target->kind == ParamKind::Int && k.step < 1) k.step = 1;
            break;
        case KnobKind::Button:
            if (k.action == ButtonAction::Reset && !target)
                return fail(0, "action \"reset\" needs param = the parameter to reset");
            if (k.action == ButtonAction::Toggle && !boolean)
                return fail(
                    0,
                    "action \"toggle\" needs param = a true/false parameter (e.g. \"ground.checkerboard\")");
            break;
        case KnobKind::Switch:
            if (!boolean)
                return fail(0,
                            "a switch needs param = a true/false parameter (e.g. \"ground.checkerboard\")");
            break;
    }
    return k;
}

}  // namespace puddle::params
