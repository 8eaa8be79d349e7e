#pragma once
// One camera frame as the GPU upload sees it: a pixel layout, its planes in memory (or a dmabuf), and
// the colour matrix and range the driver reported. A view: the source owns the bytes until its next poll.

#include <cstddef>
#include <cstdint>
#include <span>

namespace puddle::camera {

enum class PixelLayout {
    Rgba,  // 8-bit RGBA, sRGB-encoded (decoded MJPEG, mock images)
    Yuyv,  // packed 4:2:2: Y0 U Y1 V per two pixels
    Nv12,  // Y plane, then interleaved UV plane at half size both ways
};

enum class YuvMatrix { Bt601, Bt709, Bt2020 };

struct CameraImage {
    PixelLayout layout = PixelLayout::Rgba;
    int width = 0, height = 0;
    int stride = 0;                   // bytes per row of the first plane (the driver's bytesperline)
    std::span<const std::byte> data;  // every plane, as the driver laid them out (NV12: UV after height rows)
    YuvMatrix matrix = YuvMatrix::Bt601;
    bool full_range = false;     // false: Y in 16..235, UV in 16..240 (limited, "video" range)
    int dmabuf_fd = -1;          // >= 0 where the buffer was exported (VIDIOC_EXPBUF): zero-copy import
    int buffer_index = -1;       // which driver buffer: EGLImages are cached per buffer
    std::uint64_t sequence = 0;  // counts frames delivered by this source
};

}  // namespace puddle::camera
