#pragma once
// Cube crosses: six cube faces unfolded into one image. Horizontal (4 faces wide, 3 high) and vertical
// (3 wide, 4 high), in the layout most tools export:
//
//   horizontal        vertical
//   .  +Y .  .        .  +Y .
//   -X +Z +X -Z       -X +Z +X
//   .  -Y .  .        .  -Y .
//                     .  -Z .     (-Z turned upside down: it continues below -Y)
//
// Faces come out in GL order, upright as GL_TEXTURE_CUBE_MAP_POSITIVE_X + i expects them.

#include <string>

#include "assets/image.hpp"
#include "util/result.hpp"

namespace puddle::assets {

enum class CrossLayout { None, Horizontal, Vertical };

// The layout an image's proportions suggest (within 2%), whether or not its size divides into faces.
CrossLayout cross_layout(int width, int height);

// Cuts the six faces out; an error (naming `path`) when the size does not divide into square faces.
Result<CubeImages> split_cube_cross(const Image& cross, CrossLayout layout, const std::string& path);

}  // namespace puddle::assets
