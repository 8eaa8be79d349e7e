#pragma once
// Where the planes of an uncompressed camera frame lie in the driver's buffer, and how many bytes a
// complete frame needs. Subsampled chroma covers odd edges too: a 4:2:0 plane has ceil(w/2) x ceil(h/2)
// samples, a 4:2:2 row ceil(w/2) pairs (ITU-R BT.601 siting; V4L2's "Image Formats" and the kernel's
// v4l2_fill_pixfmt() size them the same way). One function answers this for the capture (which drops
// frames shorter than this) and the GPU upload (which must never read past the frame).

#include <array>
#include <cstddef>

#include "camera/camera_image.hpp"
#include "util/result.hpp"

namespace puddle::camera {

inline constexpr int max_frame_side = 16384;  // pixels; larger is a driver bug, and sizes stay in range

struct PlaneLayout {
    std::size_t offset = 0;  // bytes from the start of the frame
    int stride = 0;          // bytes from one row to the next (the driver's bytesperline)
    int row_bytes = 0;       // bytes of samples in a row; stride - row_bytes is padding
    int rows = 0;
    int texels = 0;  // texels per row as the GPU uploads it (YUYV: one RGBA8 texel per pixel pair)
    int texel_bytes = 0;
};

struct FrameLayout {
    std::array<PlaneLayout, 2> planes{};
    int count = 0;
    // The fewest bytes that hold every sample: the last plane's last row may omit its padding.
    std::size_t bytes = 0;
};

// The planes of a `layout` frame of width x height pixels whose first plane has `stride` bytes per row
// (NV12: the interleaved chroma plane follows the luma rows with the same stride). An error names the
// format, the size and what does not fit, for the caller to prefix with where it came from:
// "NV12 65x48: bytesperline 65 is shorter than the 66 bytes of a chroma row", or a side outside
// 1..max_frame_side.
Result<FrameLayout> frame_layout(PixelLayout layout, int width, int height, int stride);

// "RGBA", "YUYV", "NV12".
const char* layout_name(PixelLayout layout);

}  // namespace puddle::camera
