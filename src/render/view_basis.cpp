#include "render/view_basis.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace puddle::render {

ViewBasis view_basis(glm::vec3 eye, glm::vec3 target, float fov_degrees, float aspect) {
    ViewBasis b;
    const glm::vec3 forward = target - eye;
    if (glm::length(forward) > 1e-6f) b.forward = glm::normalize(forward);
    const glm::vec3 right = glm::cross(b.forward, glm::vec3(0, 1, 0));
    b.right = glm::length(right) > 1e-6f ? glm::normalize(right) : glm::vec3(1, 0, 0);
    b.up = glm::cross(b.right, b.forward);
    const float tan_half = std::tan(glm::radians(fov_degrees) * 0.5f);
    b.scale = {tan_half * aspect, tan_half};
    return b;
}

}  // namespace puddle::render
