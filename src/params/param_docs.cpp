#include "params/param_docs.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace puddle::params {

namespace {
std::string range_cell(const ParamDecl& d) {
    switch (d.kind) {
        case ParamKind::Bool:
            return "true/false";
        case ParamKind::Enum:
            return fmt::format("{}", fmt::join(d.choices, ", "));
        case ParamKind::Path:
            return "text";
        default: {
            auto num = [](double v) { return fmt::format("{}", v); };
            return fmt::format("{} to {}{}", num(d.min), num(d.max),
                               d.unit.empty() ? "" : fmt::format(" {}", d.unit));
        }
    }
}
}  // namespace

std::string format_params_list() {
    std::string out;
    std::string_view section;
    for (const ParamDecl& d : param_decls()) {
        const std::string_view s = d.name.substr(0, d.name.find('.'));
        if (s != section) out += fmt::format("{}[{}]\n", out.empty() ? "" : "\n", s), section = s;
        out += fmt::format("  {:<26} {:<6} default {:<22} {}\n  {:<26} {}\n", d.name, kind_name(d.kind),
                           format_value(d.default_value), range_cell(d), "", d.help);
    }
    return out;
}

std::string format_params_markdown() {
    std::string out = "| parameter | type | default | range | what it does |\n|---|---|---|---|---|\n";
    for (const ParamDecl& d : param_decls())
        out += fmt::format("| `{}` | {} | `{}` | {} | {} |\n", d.name, kind_name(d.kind),
                           format_value(d.default_value), range_cell(d), d.help);
    return out;
}

std::string format_effective(const Params& params, std::string_view preset,
                             std::span<const int> schedule_entries,
                             std::span<const std::string> schedule_presets) {
    std::string out = fmt::format(
        "# Effective values; after each, where it came from (default < preset < config < schedule < "
        "knob or remote < --set).\n# preset: {}{}{}\n",
        preset.empty() ? "none" : preset,
        schedule_presets.empty() ? "" : "; over it, active now: ", fmt::join(schedule_presets, ", "));
    for (const ParamDecl& d : param_decls()) {
        const ParamSource s = params.source(d.id);
        const auto k = static_cast<std::size_t>(d.id);
        std::string detail;
        if (s == ParamSource::Preset) detail = fmt::format(" {}", preset);
        if (s == ParamSource::Schedule && k < schedule_entries.size() && schedule_entries[k] > 0)
            detail = fmt::format("[{}]", schedule_entries[k]);
        out += fmt::format("{:<26} = {:<24} # {}{}\n", d.name, format_value(params.at(d.id)), source_name(s),
                           detail);
    }
    return out;
}

}  // namespace puddle::params
