#pragma once
// The puddle render pass: draws the scene for the camera into the frame target (REFERENCE.md §1).
// environment_override: a cube sampled in place of env.cube (the camera environment while it streams).

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "render/puddle_variant.hpp"
#include "systems/common/render_target.hpp"
#include "systems/sky/camera_environment.hpp"
#include "systems/sky/cloud_layer_system.hpp"
#include "systems/sky/environment_system.hpp"
#include "systems/water/surface_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

using PuddlePipelines =
    render::PipelineCache<render::PuddleVariant, render::puddle_variant_count, render::variant_index>;

// Resource: the puddle shader's variants (render/puddle_variant.hpp), each compiled on first use and
// kept, so a knob that flips between two looks compiles each once.
struct PuddleRenderer {
    PuddlePipelines variants;
    bool surface_unorm = false;

    // The pipeline for `v` once built; until then (a build off the frame thread) the variant drawn last,
    // so a knob that needs a new variant switches the picture in one frame when it is ready, and the
    // variant drawn last also when `v` fails to build (logged once). Null when none was ever ready.
    const render::BuiltPipeline* pipeline(gpu::Device& device, const render::PuddleVariant& v);
};

// Compiles the variant these parameters select, so a shader that does not build stops start-up.
// How the render pass maps the surface onto the water (puddle.frag's u_surface_map and the rest):
// uv = xz * uv.xy + uv.zw; the world slope per world unit of height difference over two texels; world
// units per stored height unit; the normal's tilt per stored height difference.
struct SurfaceMapping {
    glm::vec4 uv{};
    glm::vec2 slope_scale{};
    float height_units = 0.0f;
    float normal_scale = 0.0f;
};
SurfaceMapping surface_mapping(const params::Params& params, const Surface& surface);

Result<void> build_puddle_renderer(gpu::Device& device, const Surface& surface, const Environment& env,
                                   const params::Params& params, PuddleRenderer& renderer);

// Render stage: the puddle, reflecting the camera's cube while it streams, else the sky.
void puddle_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const Clouds& clouds,
                   PuddleRenderer& renderer, const RenderTarget& target, const CameraEnvironment& camera);

// The pass itself. `variant` forces one (tests compare variants); by default the parameters choose.
void render_system(gpu::Device& device, const params::Params& params, const Surface& surface,
                   const Environment& env, const Ground& ground, const Clouds& clouds,
                   PuddleRenderer& renderer, const RenderTarget& target,
                   const gpu::Texture* environment_override = nullptr,
                   const render::PuddleVariant* variant = nullptr);

}  // namespace puddle::systems
