#pragma once
// The eye: a pinhole camera as the fullscreen shaders take it (forward, right and up axes and the half
// extents of the image plane at distance 1), worked out once per frame on the CPU, not per pixel. Called
// the view in the code, so that "camera" means only the V4L2 feed; the config's camera.* keys keep their
// names.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace puddle::render {

struct ViewBasis {
    glm::vec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};
    glm::vec2 scale{1, 1};  // tan(fov / 2) * (aspect, 1)
};

// Degenerate input (eye on the target, looking straight down) still gives a usable basis.
ViewBasis view_basis(glm::vec3 eye, glm::vec3 target, float fov_degrees, float aspect);

}  // namespace puddle::render
