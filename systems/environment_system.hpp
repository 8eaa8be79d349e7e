#pragma once
// The environment (the reflected sky cubemap) and the ground texture: loaded from the files the config
// names, or made procedurally, with mipmaps. 8-bit images upload as sRGB textures (the sampler decodes
// them to linear); HDR images stay linear: a half-float cube where the GPU can render into one (its
// mipmaps need that), else RGBM RGBA8 that the puddle pass decodes. Start-up failures are errors
// with exit code 3 (5 for a cube or texture that does not fit in GPU memory); a change of
// environment.image, environment.face_size or ground.image at run time reloads, and a failed reload logs
// one line and keeps what is shown. A live cube that does not fit tries smaller faces first
// (create_environment_cube; the floor is smallest_face_size in environment_system.cpp).

#include <string>

#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct Environment {
    gpu::Texture cube;
    gpu::Sampler sampler;
    std::string source;  // for logs
    bool rgbm = false;   // texels are RGBM RGBA8: the shader decodes them (colour.glsl)
    bool hdr = false;    // linear radiance beyond 1 is possible
    // The parameter values last asked for, loaded or not: a change triggers a reload, a failure is not
    // retried.
    std::string requested_image;
    int requested_face_size = 0;
};

// Resource.
struct Ground {
    gpu::Texture texture;
    gpu::Sampler sampler;
    std::string source;
    std::string requested_image;
};

Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env);
Result<void> load_ground(gpu::Device& device, const params::Params& params, Ground& ground);

// Input stage: reloads the environment or the ground when their parameters change.
void environment_reload_system(ecs::World& world);

}  // namespace puddle::systems
