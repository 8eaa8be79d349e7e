#pragma once
// The colour target a display hands to the render system for one frame.

#include <glm/vec2.hpp>

namespace puddle::gpu {

class Texture;

struct FrameTarget {
    const Texture* texture = nullptr;  // null: the current EGL surface's framebuffer (framebuffer 0)
    glm::ivec2 size{0, 0};
    int face = 0;   // cube textures: the face rendered into (GL order +X, -X, +Y, -Y, +Z, -Z)
    int level = 0;  // the mip level rendered into (size is that level's)
};

}  // namespace puddle::gpu
