#pragma once
// The remote screenshot's picture: the frame read back (RGBA8, top row first), scaled down to at most
// `max_width` pixels wide (box filter; the height keeps the aspect, at least 1 pixel) and encoded as
// JPEG with libjpeg-turbo (camera/mjpeg_encoder.hpp). Runs on a worker thread, never the frame thread.

#include <string>

#include "assets/image.hpp"

namespace puddle::systems {

inline constexpr int screenshot_jpeg_quality = 85;

// The JPEG's bytes; empty when the image is empty or not RGBA8.
std::string screenshot_jpeg(const assets::Image& frame, int max_width);

// The RGB pixels of `frame` scaled to `width` x `height` (each output pixel the mean of the source pixels
// it covers).
std::string scaled_rgb(const assets::Image& frame, int width, int height);

}  // namespace puddle::systems
