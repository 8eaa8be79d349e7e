#include "render/param_uniforms.hpp"

#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

namespace puddle::render {

namespace {

// "u_water_" names a parameter section: the uniform must then be a parameter's.
bool has_section_prefix(std::string_view uniform) {
    for (const params::ParamDecl& d : params::param_decls()) {
        const std::string_view section = d.name.substr(0, d.name.find('.'));
        if (uniform.size() > section.size() + 3 && uniform.starts_with("u_") &&
            uniform.substr(2, section.size()) == section && uniform[2 + section.size()] == '_')
            return true;
    }
    return false;
}

}  // namespace

Result<ParamBinding> bind_params(const gpu::Pipeline& pipeline) {
    ParamBinding binding;
    for (const std::string& name : pipeline.uniform_names()) {
        const params::ParamDecl* match = nullptr;
        for (const params::ParamDecl& d : params::param_decls())
            if (d.uniform == name) match = &d;
        if (match) {
            if (match->kind != params::ParamKind::Path)
                binding.slots.push_back({pipeline.uniform(name), match});
            continue;
        }
        if (has_section_prefix(name)) {
            std::string guess(name.substr(2));
            guess[guess.find('_')] = '.';
            return make_error(ExitCode::Runtime,
                              "gpu: pipeline '{}': uniform {} is no parameter (did you mean {}?)",
                              pipeline.label(), name, params::nearest_param_name(guess));
        }
    }
    return binding;
}

void set_param_uniforms(gpu::RenderPass& pass, const ParamBinding& binding, const params::Params& params) {
    using params::ParamKind;
    for (const ParamBinding::Slot& slot : binding.slots) {
        const params::ParamDecl& d = *slot.decl;
        if (d.kind == ParamKind::Enum) {  // the shader sees the choice's index (TONEMAP_* and the like)
            pass.set(slot.location, params.choice_index(d.id));
            continue;
        }
        std::visit(
            [&](const auto& value) {
                using T = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<T, bool>)
                    pass.set(slot.location, value ? 1 : 0);
                else if constexpr (!std::is_same_v<T, std::string>)  // paths have no uniform
                    pass.set(slot.location, value);
            },
            params.at(d.id));
    }
}

}  // namespace puddle::render
