#pragma once
// Shader uniforms straight from the registry: every numeric, boolean and colour parameter is offered to
// the pass as u_<section>_<key> (rain.intensity -> u_rain_intensity); uniforms a shader does not
// declare are skipped. Nothing repeats a parameter's name in C++.

#include "gpu/render_pass.hpp"
#include "params/param_store.hpp"

namespace puddle::systems {

void set_param_uniforms(gpu::RenderPass& pass, const params::Params& params);

}  // namespace puddle::systems
