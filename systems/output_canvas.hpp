#pragma once
// The canvas between the scene and the screen, for what the display cannot do itself:
// - display.rotation (0, 90, 180, 270, clockwise as seen on the screen), done in GL: the scene renders
//   upright into a canvas the size of the turned screen, and a last pass turns it onto the display;
// - render.scale below 1: the canvas is that fraction of the screen, and the last pass scales it up
//   with bilinear filtering.
// With neither, the scene renders straight to the display and this costs nothing.

#include "gpu/device.hpp"
#include "params/param_store.hpp"

namespace puddle::systems {

// Resource.
struct OutputCanvas {
    int quarter_turns = 0;
    bool scaled = false;  // the canvas is smaller than the (turned) screen
    gpu::Texture canvas;
    glm::ivec2 canvas_size{0, 0};
    gpu::Pipeline pipeline;    // exact quarter turns: one texel per screen pixel
    gpu::Pipeline upscale;     // turns and scales up, filtering
    gpu::Sampler sampler;      // nearest
    gpu::Sampler smooth;       // bilinear
    gpu::FrameTarget display;  // this frame's display target
    bool unavailable = false;  // its shaders failed to build: said once, then the picture stays as rendered
    glm::ivec2 failed_size{0,
                           0};  // a canvas the GPU could not make: said once, unturned until the size changes
};

// Called before each frame: remembers the display target and returns where the scene should render
// (the display, or the canvas, made or resized as the rotation, the scale and the display size need).
gpu::FrameTarget begin_canvas_frame(gpu::Device& device, const params::Params& params, OutputCanvas& canvas,
                                    gpu::FrameTarget display);
// Present stage, before the frame is shown: turns and scales the canvas onto the display (nothing
// when the scene rendered to the display).
void output_canvas_system(gpu::Device& device, const OutputCanvas& canvas);

}  // namespace puddle::systems
