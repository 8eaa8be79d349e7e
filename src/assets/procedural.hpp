#pragma once
// Default assets made in code, so the program needs no files.

#include <cstdint>

#include "assets/image.hpp"

namespace puddle::assets {

// A night sky over a city: deep blue zenith, a warm light-polluted horizon, stars, a few lit windows
// and street lights near the horizon (they give the ripples something to glint with). sRGB, RGBA8.
CubeImages night_sky_cubemap(int face_size, std::uint64_t seed = 7);

}  // namespace puddle::assets
