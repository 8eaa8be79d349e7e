#pragma once
// MJPEG frames to RGBA with libjpeg-turbo. A damaged frame is an error, never a crash and never a
// picture: the library's error exit is caught, and so are its corrupt-data warnings (a truncated frame,
// JWRN_JPEG_EOF, would otherwise decode with grey where the data ran out). The output buffer is reused,
// so steady-state decoding does not allocate.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "util/result.hpp"

namespace puddle::camera {

class MjpegDecoder {
public:
    // Decodes one JPEG into rgba() (width * height * 4 bytes). The frame must have the negotiated size.
    // An error's message is the short reason for the caller's log line: "premature end of data",
    // "Corrupt JPEG data: bad Huffman code" (libjpeg's words), "a 320x240 frame in a 64x48 stream".
    // After an error rgba() holds a partial picture and must not be shown.
    Result<void> decode(std::span<const std::byte> jpeg, int expected_width, int expected_height);
    std::span<const std::byte> rgba() const { return rgba_; }

private:
    std::vector<std::byte> rgba_;
};

}  // namespace puddle::camera
