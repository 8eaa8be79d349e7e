#pragma once
// The environment (the reflected sky cubemap) and the ground texture: loaded from the files the config
// names, or made procedurally, with mipmaps. 8-bit images upload as sRGB textures (the sampler decodes
// them to linear); HDR images stay linear: a half-float cube where the GPU can render into one (its
// mipmaps need that), else RGBM RGBA8 that the puddle pass decodes. Start-up failures are errors
// with exit code 3 (5 for a cube or texture that does not fit in GPU memory). A change of
// environment.image, environment.face_size or ground.image at run time reloads without stopping the
// frames: the files are read and decoded on a worker thread, the sky's GPU half runs in bounded steps on
// the frame thread (environment_build.hpp), and what is shown changes in one frame once the new one is
// complete. A live cube that does not fit tries smaller faces first (create_environment_cube; the floor
// is fallback_floor in environment_system.cpp). A failed reload logs one line and keeps what is shown.

#include <optional>
#include <string>

#include "assets/image.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/sky/environment_build.hpp"
#include "util/background_job.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct Environment {
    gpu::Texture cube;
    gpu::Sampler sampler;
    std::string source;  // for logs
    bool rgbm = false;   // texels are RGBM RGBA8: the shader decodes them (colour.glsl)
    bool hdr = false;    // linear radiance beyond 1 is possible
    // The procedural sky without its clouds: alpha says how much the drifting layer (Clouds) may cover
    // each texel; the puddle shader draws them (CLOUD_LAYER). Else the cube is the whole sky.
    bool cloud_room = false;
    render::EquirectPipelines panorama_pipelines;  // converting panoramas: compiled once, kept for reloads
    // The parameter values last asked for, loaded or not: a change triggers a reload, a failure is not
    // retried.
    std::string requested_image;
    int requested_face_size = 0;
};

// Resource: the ground.image texture. The checkerboard and the procedural setts (the default) are drawn by
// the shader and need none: until an image is asked for and shows (ground.checkerboard false, ground.image
// set), `texture` is a 1x1 placeholder and nothing is read. A new image is read on the worker; the setts,
// or the image shown before, stay on screen until it is ready.
struct Ground {
    gpu::Texture texture;
    gpu::Sampler sampler;
    std::string source;  // what shows, for logs: the image's path, or which ground the shader draws
    // The ground.image last asked for, loaded or not; none while no image has been asked for since
    // ground.image was last empty.
    std::optional<std::string> requested_image;
    bool made = false;  // `texture` holds an image (else the placeholder)
};

// The ground's CPU half: the image at `path` (not empty) read, as sRGB, halved until the GPU takes it and
// it is at most ground_max_size a side: a ground seen through water shows no more, and the upload and
// mipmaps, on the frame thread, stay short (a 16384-texel image froze a frame for seconds on llvmpipe).
// Errors name ground.image and the file.
inline constexpr int ground_max_size = 2048;
struct PreparedGround {
    assets::Image image;
    std::string source;
};
Result<PreparedGround> prepare_ground(const std::string& path, int max_texture_size);

// Resource: live reloads in progress. At most one of each is decoded at a time; a newer change of the
// parameters makes an older one's result stale (it is dropped, never shown).
struct EnvironmentReload {
    BackgroundJob<Result<PreparedEnvironment>> environment;
    std::optional<EnvironmentBuild> environment_build;
    BackgroundJob<Result<PreparedGround>> ground;
    int fallback_floor = EnvironmentBuild::no_fallback;  // the smallest faces the reload under way may use

    // True while a new sky or ground is being read, decoded or built.
    bool pending() const { return environment.busy() || environment_build.has_value() || ground.busy(); }
};

// Start-up: all of it at once, on this thread.
Result<void> load_environment(gpu::Device& device, const params::Params& params, Environment& env);
Result<void> load_ground(gpu::Device& device, const params::Params& params, Ground& ground);

// Input stage: starts a reload when the parameters change, takes finished decodes, does one step of a
// sky's GPU build and shows what is complete.
void environment_reload_system(gpu::Device& device, const params::Params& params, Environment& env,
                               Ground& ground, EnvironmentReload& reload);

}  // namespace puddle::systems
