#pragma once
// A large image uploaded in bands of rows, one band a call, so that no frame spends long in the driver
// (an 8192x4096 float panorama is half a gigabyte of floats to convert to half floats).

#include <algorithm>
#include <cstddef>
#include <span>

#include "assets/image.hpp"
#include "gpu/texture.hpp"

namespace puddle::render {

// Uploads the next band of `image`, at most `texel_budget` texels (at least one row), into `level` (and
// `face`) of `texture`, from row `next_row` on, and advances it. True once the last row is up (at once,
// uploading nothing, when no row is left).
inline bool upload_next_band(gpu::Texture& texture, const assets::Image& image, int level, int face,
                             int& next_row, long texel_budget) {
    if (next_row >= image.height) return true;  // nothing left (an empty image has no rows to upload)
    const int rows = static_cast<int>(
        std::clamp(texel_budget / std::max(image.width, 1), 1L, static_cast<long>(image.height - next_row)));
    const std::size_t row_bytes = std::size_t(image.width) * image.bytes_per_pixel();
    texture.upload_rows(std::as_bytes(std::span(image.data))
                            .subspan(std::size_t(next_row) * row_bytes, std::size_t(rows) * row_bytes),
                        level, face, next_row, rows);
    next_row += rows;
    return next_row >= image.height;
}

}  // namespace puddle::render
