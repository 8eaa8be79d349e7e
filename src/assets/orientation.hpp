#pragma once
// The EXIF/TIFF Orientation tag (0x0112, values 1 to 8): how a camera stored the pixels, and the turn
// that shows them as image viewers do. A JPEG sky stored rotated 180 degrees with tag 3 rendered upside
// down, and a 2:1 panorama stored portrait with tag 6 or 8 was refused as 1:2, before this was applied.
// Tags, as the EXIF 2.32 standard (and PIL's ImageOps.exif_transpose) read them, for the stored rows:
//   1 upright  2 mirrored  3 turned 180  4 upside down (mirrored vertically)
//   5 transposed  6 needs 90 clockwise  7 transversed  8 needs 90 anticlockwise
// Values outside 1..8 are taken as 1 (upright), as viewers do.

#include <cstddef>

namespace puddle::assets {

inline int valid_orientation(int orientation) {
    return orientation >= 1 && orientation <= 8 ? orientation : 1;
}

// Tags 5 to 8 swap width and height: the upright image is stored_height wide.
inline bool orientation_swaps_axes(int orientation) {
    return valid_orientation(orientation) >= 5;
}

// Copies `src` (stored_width x stored_height pixels of `channels` values, top row first) into `dst`
// upright (stored_height x stored_width for tags 5 to 8). `src` and `dst` must not overlap.
template <class T>
void orient_pixels(const T* src, std::size_t stored_width, std::size_t stored_height, std::size_t channels,
                   int orientation, T* dst) {
    const std::size_t w = stored_width, h = stored_height;
    const int o = valid_orientation(orientation);
    const bool swap = orientation_swaps_axes(o);
    const std::size_t out_w = swap ? h : w, out_h = swap ? w : h;
    for (std::size_t y = 0; y < out_h; ++y)
        for (std::size_t x = 0; x < out_w; ++x) {
            std::size_t sx = x, sy = y;  // the stored pixel shown at (x, y)
            switch (o) {
                case 2:
                    sx = w - 1 - x;
                    break;
                case 3:
                    sx = w - 1 - x;
                    sy = h - 1 - y;
                    break;
                case 4:
                    sy = h - 1 - y;
                    break;
                case 5:
                    sx = y;
                    sy = x;
                    break;
                case 6:
                    sx = y;
                    sy = h - 1 - x;
                    break;
                case 7:
                    sx = w - 1 - y;
                    sy = h - 1 - x;
                    break;
                case 8:
                    sx = w - 1 - y;
                    sy = x;
                    break;
                default:
                    break;
            }
            const T* s = src + (sy * w + sx) * channels;
            T* d = dst + (y * out_w + x) * channels;
            for (std::size_t c = 0; c < channels; ++c) d[c] = s[c];
        }
}

}  // namespace puddle::assets
