#pragma once
// The canvas between the scene and the screen, for what the display cannot do itself:
// - display.rotation (0, 90, 180, 270, clockwise as seen on the screen), plus wall.rotation's quarter
//   turns, done in GL: the scene renders upright into a canvas the size of the turned screen, and a last
//   pass turns it onto the display;
// - render.scale below 1 (or the adaptive scale's, systems/output/adaptive_scale.hpp): the canvas is that
//   fraction of the screen, and the last pass scales it up with bilinear filtering;
// - display.brightness below 1: the last pass multiplies every colour channel by it, once, on the
//   display-encoded values (0.5 halves each 8-bit value: about a fifth of the light on an sRGB screen).
// With none of them, the scene renders straight to the display and this costs nothing.

#include <glm/vec3.hpp>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"

namespace puddle::systems {

// The last pass's two shaders: exact quarter turns (one texel per screen pixel), or turned and scaled up
// with filtering.
enum class CanvasPass { turn, turn_and_scale };
inline constexpr std::size_t canvas_pass_count = 2;
using CanvasPipelines = render::PipelineCache<CanvasPass, canvas_pass_count, render::enum_index<CanvasPass>>;

// Resource.
struct OutputCanvas {
    int quarter_turns = 0;
    bool scaled = false;   // the canvas is smaller than the (turned) screen
    float brightness = 1;  // display.brightness this frame
    gpu::Texture canvas;
    glm::ivec2 canvas_size{0, 0};
    // Each built the first time it is needed; one that fails is said once, then the picture stays unturned.
    CanvasPipelines pipelines{"showing the picture unturned, at full size"};
    gpu::Sampler sampler;      // nearest
    gpu::Sampler smooth;       // bilinear
    gpu::FrameTarget display;  // this frame's display target
    // A canvas the GPU could not make: said once, unturned until the size changes.
    glm::ivec2 failed_size{0, 0};
    glm::ivec3 logged_layout{0, 0, -1};  // display size and turn of the last info line
};

// Start-up: builds the shader the configured rotation and scale need on a screen of `display_size`, so the
// first frame is turned; an error (the shader does not build) stops start-up.
Result<void> prepare_output_canvas(gpu::Device& device, const params::Params& params, OutputCanvas& canvas,
                                   glm::ivec2 display_size);
// Called before each frame: remembers the display target and returns where the scene should render
// (the display, or the canvas, made or resized as the rotation, `scale` (render.scale, or the adaptive
// scale's) and the display size need).
// The canvas's shader is built off the frame thread; until it is ready the scene renders to the display.
gpu::FrameTarget begin_canvas_frame(gpu::Device& device, const params::Params& params, OutputCanvas& canvas,
                                    gpu::FrameTarget display, float scale);
// Present stage, before the frame is shown: turns and scales the canvas onto the display (nothing
// when the scene rendered to the display).
void output_canvas_system(gpu::Device& device, const OutputCanvas& canvas);

}  // namespace puddle::systems
