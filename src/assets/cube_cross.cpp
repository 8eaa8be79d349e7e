#include "assets/cube_cross.hpp"

#include <array>
#include <cmath>
#include <cstring>

namespace puddle::assets {
namespace {

struct Cell {
    int column, row;
    bool upside_down;
};

// Per face in GL order (+X, -X, +Y, -Y, +Z, -Z): where it sits in the cross.
constexpr std::array<Cell, 6> horizontal_cells{
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}};
constexpr std::array<Cell, 6> vertical_cells{
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}};

bool near_ratio(int width, int height, double ratio) {
    return height > 0 && std::abs(double(width) / double(height) / ratio - 1.0) <= 0.02;
}

Image cut(const Image& src, int x0, int y0, int size, bool upside_down) {
    Image face = Image::make(size, size, src.format);
    const std::size_t bpp = src.bytes_per_pixel();
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            // Turned by 180 degrees: the last pixel of the cell becomes the first.
            const int sx = upside_down ? x0 + size - 1 - x : x0 + x;
            const int sy = upside_down ? y0 + size - 1 - y : y0 + y;
            std::memcpy(face.data.data() + (std::size_t(y) * size + x) * bpp,
                        src.data.data() + (std::size_t(sy) * src.width + sx) * bpp, bpp);
        }
    }
    return face;
}

}  // namespace

CrossLayout cross_layout(int width, int height) {
    if (near_ratio(width, height, 4.0 / 3.0)) return CrossLayout::Horizontal;
    if (near_ratio(width, height, 3.0 / 4.0)) return CrossLayout::Vertical;
    return CrossLayout::None;
}

Result<CubeImages> split_cube_cross(const Image& cross, CrossLayout layout, const std::string& path) {
    const bool horizontal = layout == CrossLayout::Horizontal;
    const int columns = horizontal ? 4 : 3, rows = horizontal ? 3 : 4;
    const int size = cross.width / columns;
    if (layout == CrossLayout::None || cross.width % columns != 0 || cross.height % rows != 0 ||
        cross.height / rows != size || size == 0)
        return make_error(
            ExitCode::Asset,
            "environment.image: {} is {}x{}: a {} cube cross must be {} square faces wide and {} high "
            "(e.g. {}x{})",
            path, cross.width, cross.height, horizontal ? "horizontal" : "vertical", columns, rows,
            columns * 256, rows * 256);
    CubeImages cube;
    cube.source = path;
    const auto& cells = horizontal ? horizontal_cells : vertical_cells;
    for (std::size_t i = 0; i < 6; ++i)
        cube.faces[i] = cut(cross, cells[i].column * size, cells[i].row * size, size, cells[i].upside_down);
    return cube;
}

}  // namespace puddle::assets
