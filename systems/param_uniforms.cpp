#include "systems/param_uniforms.hpp"

namespace puddle::systems {

void set_param_uniforms(gpu::RenderPass& pass, const params::Params& params) {
    using params::ParamKind;
    for (const params::ParamDecl& d : params::param_decls()) {
        switch (d.kind) {
            case ParamKind::Float: pass.set(d.uniform, params.f(d.id)); break;
            case ParamKind::Int: pass.set(d.uniform, params.i(d.id)); break;
            case ParamKind::Bool: pass.set(d.uniform, params.b(d.id) ? 1 : 0); break;
            case ParamKind::Vec3:
            case ParamKind::Color: pass.set(d.uniform, params.v3(d.id)); break;
            case ParamKind::Enum: {  // the index of the choice, in params.def order
                const std::string& value = params.s(d.id);
                for (std::size_t k = 0; k < d.choices.size(); ++k)
                    if (d.choices[k] == value) pass.set(d.uniform, static_cast<int>(k));
                break;
            }
            case ParamKind::Path: break;  // files are loaded on the CPU, not uniforms
        }
    }
}

}  // namespace puddle::systems
