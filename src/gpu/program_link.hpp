#pragma once
// Compiling and linking a pipeline's GL program: the slow part of making a pipeline, and the only part
// that may run on a worker thread (any context sharing objects with the frame thread's; see
// gpu/pipeline_compiler.hpp). Reading the program's uniforms and binding its samplers stays on the frame
// thread (Device).

#include "gpu/handle.hpp"
#include "gpu/pipeline.hpp"
#include "util/result.hpp"

namespace puddle::gpu {

// The linked program for desc, owned by the caller. Errors name the shader file and line, as
// Device::create_pipeline documents: "gpu: pipeline 'ocean': ocean.frag:31: error: ...".
Result<GlHandle<detail::delete_program>> link_program(const PipelineDesc& desc);

}  // namespace puddle::gpu
