#pragma once
// The largest image Puddle decodes. A file's header can claim any size (a few bytes of .hdr text say
// 100000x100000); the limits are checked from that header, before a byte of pixels is allocated or
// decoded, so a wrong or hostile file costs an error message, not the memory of a kiosk.
//
// 16384 pixels a side is the largest texture any GLES 3 driver Puddle meets takes (most take 8192; bigger
// pictures are halved, see image.hpp); 1 GiB of decoded pixels holds a 16384x8192 8-bit panorama or an
// 8192x8192 float one (16 bytes a pixel).

#include <cstddef>
#include <string>

#include "assets/image.hpp"
#include "util/result.hpp"

namespace puddle::assets {

inline constexpr int max_image_side = 16384;                          // pixels, width and height
inline constexpr std::size_t max_image_bytes = std::size_t{1} << 30;  // decoded RGBA, bytes

// Ok when a `width` x `height` image of `format` fits the limits; else an error (exit code 3) naming
// `path`, the size and the limit, e.g. "image: sky.hdr: 20000x10000 is too large: at most 16384 pixels a
// side".
Result<void> check_image_size(const std::string& path, int width, int height, PixelFormat format);

}  // namespace puddle::assets
