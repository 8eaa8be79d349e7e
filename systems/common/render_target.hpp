#pragma once
// Where this frame's scene passes draw, shared by every look and the output stage.

#include "gpu/device.hpp"
#include "render/view_window.hpp"

namespace puddle::systems {

// Resource: where this frame goes, and which window of the whole view it shows (a video wall's tile;
// all of it on a single screen), set by the begin-frame system from the display each frame. The scene
// passes draw with view_window.vert and set u_view_window from `view`.
struct RenderTarget {
    gpu::FrameTarget target;
    render::ViewWindow view;
};

}  // namespace puddle::systems
