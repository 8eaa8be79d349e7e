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

}  // namespace puddle::params
