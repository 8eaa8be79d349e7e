#pragma once
// The city half of the procedural night sky (procedural.hpp): what stands between the viewer and the sky.
// The viewer stands on a wet street, eye height 1 unit; around them a ring of near buildings (facades 14 to
// 34 units away whose roofs reach 10 to 60 degrees up, with floors of lit windows and lit shop fronts at
// street level), behind those a far skyline, and below the horizon the paved street lit by lamp pools and
// the city's glow, so that every direction below the horizon is lit (the steep sides of a drop's crater
// reflect it). Linear radiance; windows, shop fronts, lamps and the moon reach past 1 (HDR). Internal to
// src/assets.

#include <cstdint>

#include "assets/procedural_shading.hpp"

namespace puddle::assets::city {

struct CityView {
    std::uint32_t key = 0;
    float pix_rad = 0.006f;      // about one texel, in radians, for antialiasing
    float moon_az_deg = 270.0f;  // the buildings in front of the moon stay below it
    float moon_el_deg = 35.0f;
    shading::Vec3 haze;  // light-polluted air at the horizon (the sky's horizon colour)
    shading::Vec3 band;  // the hot band just above the roofs
};

// The city along the unit direction d at azimuth az_deg (0 towards -Z, increasing towards +X, 0 to 360),
// drawn over `sky` (what is behind it); `glow` is the city's brightness in this direction (about 0.5 to
// 1.2). open_sky: the share of the result that is `sky` (0 where a building or the street is in front).
shading::Vec3 city(const CityView& view, shading::Vec3 d, float az_deg, shading::Vec3 sky, float glow,
                   float& open_sky);

}  // namespace puddle::assets::city
