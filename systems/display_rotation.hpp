#pragma once
// Display rotation (display.rotation: 0, 90, 180, 270, clockwise as seen on the screen), done in GL:
// with a turn, the scene renders upright into a canvas the size of the turned screen, and a last pass
// turns it onto the display. With none, the scene renders straight to the display and this costs
// nothing.

#include "gpu/device.hpp"
#include "params/param_store.hpp"

namespace puddle::systems {

// Resource.
struct DisplayRotation {
    int quarter_turns = 0;
    gpu::Texture canvas;
    glm::ivec2 canvas_size{0, 0};
    gpu::Pipeline pipeline;
    gpu::Sampler sampler;
    gpu::FrameTarget display;  // this frame's display target
};

// Called before each frame: remembers the display target and returns where the scene should render
// (the display, or the canvas, made or resized as the rotation and display size need).
gpu::FrameTarget begin_rotated_frame(gpu::Device& device, const params::Params& params, DisplayRotation& rotation,
                                     gpu::FrameTarget display);
// Present stage, before the frame is shown: turns the canvas onto the display (nothing without a turn).
void rotation_system(gpu::Device& device, const DisplayRotation& rotation);

}  // namespace puddle::systems
