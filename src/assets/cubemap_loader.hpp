#pragma once
// Environment cubemaps from files: a folder holding px/nx/py/ny/pz/nz in any common image format, or six
// explicit paths. All faces must be square and of one size. Faces come back as read_color_image gives
// them (8-bit sRGB or linear float); when any face is float, all are made linear float.

#include <array>
#include <string>

#include "assets/image.hpp"
#include "util/result.hpp"

namespace puddle::assets {

Result<CubeImages> load_cubemap_folder(const std::string& folder);
Result<CubeImages> load_cubemap_faces(const std::array<std::string, 6>& paths);

}  // namespace puddle::assets
