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
            case ParamKind::Enum:
            case ParamKind::Path: break;  // chosen by #define or on the CPU, not uniforms
        }
    }
}

}  // namespace puddle::systems
