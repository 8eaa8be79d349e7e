#pragma once
// RGB pixels to a JPEG with libjpeg-turbo: the decoder's twin, for frames of known content where there is
// no camera (the benchmark's MJPEG frame, the fake V4L2 device in the tests).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace puddle::camera {

// `rgb`: width * height * 3 bytes, rows top first. `quality`: 1 to 100, as libjpeg takes it. Empty when
// the sizes do not fit the pixels.
std::vector<std::byte> encode_jpeg(std::span<const std::uint8_t> rgb, int width, int height, int quality);

}  // namespace puddle::camera
