#pragma once
// Y'CbCr to R'G'B' as one affine map for the conversion shader: rgb = matrix * (yuv - offset), with yuv
// the 8-bit samples scaled to 0..1. The range (limited or full) is folded into the matrix.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "camera/camera_image.hpp"

namespace puddle::camera {

struct YuvToRgb {
    glm::mat3 matrix{1.0f};
    glm::vec3 offset{0.0f};
};

YuvToRgb yuv_to_rgb(YuvMatrix matrix, bool full_range);

}  // namespace puddle::camera
