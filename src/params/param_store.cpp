#include "params/param_store.hpp"

namespace puddle::params {

std::string_view source_name(ParamSource s) {
    switch (s) {
        case ParamSource::Default: return "default";
        case ParamSource::Preset: return "preset";
        case ParamSource::Config: return "config";
        case ParamSource::Knob: return "knob";
        case ParamSource::CommandLine: return "--set";
    }
    return "?";
}

Params::Params() {
    for (const ParamDecl& d : param_decls()) values_[index(d.id)] = d.default_value;
}

bool Params::set(ParamId id, ParamValue value, ParamSource from) {
    const std::size_t k = index(id);
    if (from < sources_[k]) return false;
    sources_[k] = from;
    if (values_[k] != value) {
        values_[k] = std::move(value);
        ++revision_;
    }
    return true;
}

void Params::replace_with(const Params& next) {
    bool changed = false;
    for (std::size_t k = 0; k < param_count; ++k) {
        sources_[k] = next.sources_[k];
        if (values_[k] != next.values_[k]) values_[k] = next.values_[k], changed = true;
    }
    if (changed) ++revision_;
}

}  // namespace puddle::params
