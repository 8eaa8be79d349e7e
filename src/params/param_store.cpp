#include "params/param_store.hpp"

#include <algorithm>

namespace puddle::params {

std::string_view source_name(ParamSource s) {
    switch (s) {
        case ParamSource::Default:
            return "default";
        case ParamSource::Preset:
            return "preset";
        case ParamSource::Config:
            return "config";
        case ParamSource::Schedule:
            return "schedule";
        case ParamSource::Knob:
            return "knob";
        case ParamSource::Remote:
            return "remote";
        case ParamSource::CommandLine:
            return "--set";
    }
    return "?";
}

Params::Params() {
    for (const ParamDecl& d : param_decls()) store(index(d.id), d.default_value);
}

void Params::store(std::size_t k, ParamValue value) {
    values_[k] = std::move(value);
    const ParamDecl& d = param_decls()[k];
    if (d.kind != ParamKind::Enum) return;
    // set() refused any text that is no choice, so the choice is always found.
    const auto& text = std::get<std::string>(values_[k]);
    for (std::size_t c = 0; c < d.choices.size(); ++c)
        if (d.choices[c] == text) choices_[k] = static_cast<std::uint8_t>(c);
}

bool Params::set(ParamId id, ParamValue value, ParamSource from) {
    const std::size_t k = index(id);
    if (from < sources_[k]) return false;
    if (value.index() != values_[k].index()) return false;  // another kind than declared
    if (const ParamDecl& d = param_decls()[k]; d.kind == ParamKind::Enum) {
        const auto& text = std::get<std::string>(value);
        if (std::find(d.choices.begin(), d.choices.end(), text) == d.choices.end()) return false;
    }
    sources_[k] = from;
    if (values_[k] != value) {
        store(k, std::move(value));
        ++revision_;
    }
    return true;
}

void Params::replace_with(const Params& next) {
    bool changed = false;
    for (std::size_t k = 0; k < param_count; ++k) {
        sources_[k] = next.sources_[k];
        if (values_[k] != next.values_[k]) {
            values_[k] = next.values_[k];
            choices_[k] = next.choices_[k];
            changed = true;
        }
    }
    if (changed) ++revision_;
}

}  // namespace puddle::params
