#pragma once
// The environment (the reflected sky cubemap) and the ground texture: loaded from the files the config
// names, or made procedurally, and uploaded as sRGB textures (the sampler decodes them to linear)
// with mipmaps. Start-up failures are errors with exit code 3.

#include <string>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct Environment {
    gpu::Texture cube;
    gpu::Sampler sampler;
    std::string source;  // for logs
};

// Resource.
struct Ground {
    gpu::Texture texture;
    gpu::Sampler sampler;
    std::string source;
};

Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env);
Result<void> load_ground(gpu::Device& device, const params::Params& params, Ground& ground);

}  // namespace puddle::systems
