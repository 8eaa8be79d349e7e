#include "camera/frame_layout.hpp"

namespace puddle::camera {

namespace {

int half_up(int n) {
    return (n + 1) / 2;
}

}  // namespace

const char* layout_name(PixelLayout layout) {
    switch (layout) {
        case PixelLayout::Rgba:
            return "RGBA";
        case PixelLayout::Yuyv:
            return "YUYV";
        case PixelLayout::Nv12:
            return "NV12";
    }
    return "?";
}

Result<FrameLayout> frame_layout(PixelLayout layout, int width, int height, int stride) {
    if (width < 1 || height < 1 || width > max_frame_side || height > max_frame_side)
        return make_error(ExitCode::Runtime, "{} {}x{}: each side must be 1 to {} pixels",
                          layout_name(layout), width, height, max_frame_side);
    FrameLayout f;
    switch (layout) {
        case PixelLayout::Rgba:
            f.planes[0] = {
                .stride = stride, .row_bytes = width * 4, .rows = height, .texels = width, .texel_bytes = 4};
            f.count = 1;
            break;
        case PixelLayout::Yuyv:  // Y0 U Y1 V: an odd width still ends in a whole pair
            f.planes[0] = {.stride = stride,
                           .row_bytes = half_up(width) * 4,
                           .rows = height,
                           .texels = half_up(width),
                           .texel_bytes = 4};
            f.count = 1;
            break;
        case PixelLayout::Nv12:
            f.planes[0] = {
                .stride = stride, .row_bytes = width, .rows = height, .texels = width, .texel_bytes = 1};
            f.planes[1] = {.offset = static_cast<std::size_t>(stride) * static_cast<std::size_t>(height),
                           .stride = stride,
                           .row_bytes = half_up(width) * 2,
                           .rows = half_up(height),
                           .texels = half_up(width),
                           .texel_bytes = 2};
            f.count = 2;
            break;
    }
    for (int i = 0; i < f.count; ++i) {
        const PlaneLayout& p = f.planes[static_cast<std::size_t>(i)];
        if (p.stride < p.row_bytes)
            return make_error(
                ExitCode::Runtime, "{} {}x{}: bytesperline {} is shorter than the {} bytes of a {} row",
                layout_name(layout), width, height, stride, p.row_bytes, i == 0 ? "pixel" : "chroma");
    }
    const PlaneLayout& last = f.planes[static_cast<std::size_t>(f.count - 1)];
    f.bytes = last.offset + static_cast<std::size_t>(last.stride) * static_cast<std::size_t>(last.rows - 1) +
              static_cast<std::size_t>(last.row_bytes);
    return f;
}

}  // namespace puddle::camera
