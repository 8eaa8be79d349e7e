#pragma once
// Shader uniforms straight from the registry: a shader that declares u_<section>_<key> reads parameter
// section.key (rain.intensity -> u_rain_intensity), and nothing repeats a parameter's name in C++. The
// binding is worked out once, when a pipeline is built: which of its active uniforms mirror which
// parameters, at which locations. A uniform that looks like a parameter's (its prefix is a parameter
// section, u_water_...) but names none is an error, so a misspelled uniform in a shader stops start-up
// instead of leaving the value at zero. Enums reach the shader as the index of the choice, in params.def
// order; booleans as 0 or 1; paths not at all.

#include <vector>

#include "gpu/pipeline.hpp"
#include "gpu/render_pass.hpp"
#include "params/param_store.hpp"
#include "util/result.hpp"

namespace puddle::render {

struct ParamBinding {
    struct Slot {
        gpu::UniformLocation location;
        const params::ParamDecl* decl;
    };
    std::vector<Slot> slots;  // one per parameter the shader reads
};

// Errors: "gpu: pipeline 'street': uniform u_street_horizn is no parameter (did you mean street.horizon?)".
Result<ParamBinding> bind_params(const gpu::Pipeline& pipeline);

// Sets every bound parameter's uniform on the pass (whose pipeline the binding was made for).
void set_param_uniforms(gpu::RenderPass& pass, const ParamBinding& binding, const params::Params& params);

}  // namespace puddle::render
