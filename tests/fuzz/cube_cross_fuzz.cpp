// Fuzz target: the cube cross shape logic (cube_cross.hpp) for any width and height up to 768, and any
// layout asked for, not only the one cross_layout() suggests. A split either refuses with a message
// naming the path or returns six square faces that tile the cross exactly, each face's first pixel
// taken from where the documented layout puts it.

#include <array>

#include "assets/cube_cross.hpp"
#include "fuzz_support.hpp"

using namespace puddle;
using namespace puddle::assets;

namespace {

// Each pixel holds its own coordinates, so a face pixel says where in the cross it came from.
Image numbered(int width, int height) {
    Image image = Image::make(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel8(x, y);
            p[0] = static_cast<std::uint8_t>(x);
            p[1] = static_cast<std::uint8_t>(x >> 8);
            p[2] = static_cast<std::uint8_t>(y);
            p[3] = static_cast<std::uint8_t>(y >> 8);
        }
    return image;
}

struct Cell {
    int column, row;
    bool upside_down;
};
// cube_cross.hpp's drawing, per face in GL order (+X, -X, +Y, -Y, +Z, -Z).
constexpr std::array<Cell, 6> horizontal{
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}};
constexpr std::array<Cell, 6> vertical{
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 5) return 0;
    const int width = 1 + ((data[0] | data[1] << 8) % 768);
    const int height = 1 + ((data[2] | data[3] << 8) % 768);
    const CrossLayout suggested = cross_layout(width, height);
    const CrossLayout layout = data[4] % 4 == 3 ? suggested : static_cast<CrossLayout>(data[4] % 3);
    if (suggested == CrossLayout::Horizontal)
        PUDDLE_FUZZ_CHECK(width > height, "%dx%d suggested a horizontal cross", width, height);
    if (suggested == CrossLayout::Vertical)
        PUDDLE_FUZZ_CHECK(height > width, "%dx%d suggested a vertical cross", width, height);

    const Image cross = numbered(width, height);
    auto cube = split_cube_cross(cross, layout, "cross.png");
    if (!cube) {
        PUDDLE_FUZZ_CHECK(cube.error().message.find("cross.png") != std::string::npos, "no path in: %s",
                          cube.error().message.c_str());
        return 0;
    }
    PUDDLE_FUZZ_CHECK(layout != CrossLayout::None, "split %dx%d without a layout", width, height);
    const bool is_horizontal = layout == CrossLayout::Horizontal;
    const int side = is_horizontal ? width / 4 : width / 3;
    PUDDLE_FUZZ_CHECK(
        side > 0 && side * (is_horizontal ? 4 : 3) == width && side * (is_horizontal ? 3 : 4) == height,
        "%dx%d split into faces of %d", width, height, side);
    for (std::size_t i = 0; i < 6; ++i) {
        const Image& face = cube->faces[i];
        PUDDLE_FUZZ_CHECK(face.width == side && face.height == side, "face %zu is %dx%d, not %d", i,
                          face.width, face.height, side);
        const Cell c = (is_horizontal ? horizontal : vertical)[i];
        const int x = c.column * side + (c.upside_down ? side - 1 : 0);
        const int y = c.row * side + (c.upside_down ? side - 1 : 0);
        const std::uint8_t* p = face.pixel8(0, 0);
        PUDDLE_FUZZ_CHECK((p[0] | p[1] << 8) == x && (p[2] | p[3] << 8) == y,
                          "face %zu starts at (%d,%d) of the cross, expected (%d,%d)", i, p[0] | p[1] << 8,
                          p[2] | p[3] << 8, x, y);
    }
    return 0;
}
