#pragma once
// Default assets made in code, so the program needs no files.

#include <cstdint>

#include "assets/cloud_layer.hpp"
#include "assets/image.hpp"

namespace puddle::assets {

// A night city seen from a wet street, in HDR: a deep blue zenith with a few stars, a warm glow over the
// city, clouds lit from below, a moon 35 degrees up towards -X (where the default camera sees the puddle
// reflect the sky), near buildings with floors of lit windows and shop fronts, a far skyline, and below the
// horizon the paved street lit by lamps (procedural_city.hpp). Linear radiance, RGBA32F faces in GL order;
// windows, lamps and the moon reach 1.5 to 8 (HDR: they glint after tone mapping). Each texel is shaded
// once with a fixed amount of work (O(face_size^2)); the faces render on six threads where there are any.
// SkyClouds::baked: the clouds (cloud_layer_image, undrifted) are drawn into the faces, alpha 1;
// SkyClouds::drifting: they are left out, and alpha holds how much the drifting layer may cover each
// texel (cloud_layer.hpp).
enum class SkyClouds { baked, drifting };
CubeImages night_sky_cubemap(int face_size, std::uint64_t seed = 7, SkyClouds clouds = SkyClouds::baked);

// The light the drifting cloud layer is drawn in, matching the cube of the same seed.
CloudLight night_sky_cloud_light(std::uint64_t seed = 7);

// The face size the procedural sky is made at when environment.face_size is 0 (sharp enough for a 1080p
// screen: the puddle magnifies the reflected sky), and the most it is made at (six float faces of 1024
// are 100 MB).
inline constexpr int procedural_sky_face_size = 512;
inline constexpr int procedural_sky_max_face_size = 1024;

}  // namespace puddle::assets
