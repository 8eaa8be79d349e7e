#pragma once
// MJPEG frames to RGBA with libjpeg-turbo. A corrupt or truncated frame is an error, never a crash (the
// library's error exit is caught); the output buffer is reused, so steady-state decoding does not allocate.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "util/result.hpp"

namespace puddle::camera {

class MjpegDecoder {
public:
    // Decodes one JPEG into rgba() (width * height * 4 bytes). The frame must have the negotiated size.
    Result<void> decode(std::span<const std::byte> jpeg, int expected_width, int expected_height);
    std::span<const std::byte> rgba() const { return rgba_; }

private:
    std::vector<std::byte> rgba_;
};

}  // namespace puddle::camera
