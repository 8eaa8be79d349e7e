#pragma once
// A procedural paving texture for the ground under the water when no ground.image is given and the
// checkerboard is off: tileable rounded cobbles with dark joints. sRGB, RGBA8.

#include <cstdint>

#include "assets/image.hpp"

namespace puddle::assets {

Image cobblestone_ground(int size, std::uint64_t seed = 3);

}  // namespace puddle::assets
