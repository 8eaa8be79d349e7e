#pragma once
// --screenshot FILE: the frame read back, written as the file's name says. A name ending in .jpg or
// .jpeg (any case) gets a JPEG (full size, quality screenshot_jpeg_quality, libjpeg-turbo: what a
// photo-sized picture on a phone or a ticket wants); anything else, with or without .png, a PNG
// (lossless, what the golden tests compare). Both are written beside FILE and renamed over it, so a
// failed write never leaves a truncated picture behind.

#include <string>
#include <string_view>

#include "assets/image.hpp"
#include "util/result.hpp"

namespace puddle::app {

enum class ScreenshotFormat { png, jpeg };

// From the name alone: ".jpg"/".jpeg" (case-insensitive) is JPEG, everything else PNG.
ScreenshotFormat screenshot_format(std::string_view path);

// `image`: RGBA8, top row first. Errors (ExitCode::Asset): "image: PATH: cannot write: REASON".
Result<void> write_screenshot(const std::string& path, const assets::Image& image);

}  // namespace puddle::app
