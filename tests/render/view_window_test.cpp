// A screen's window of the whole view (render/view_window.hpp): the wall's size with its bezels, each
// tile's place in it (rows from the top, the view's y up), mirror mode and no wall, and clamping.
#include "render/view_window.hpp"

#include <gtest/gtest.h>

namespace puddle::render {
namespace {

using params::ParamId;
using params::ParamSource;

params::Params wall(int columns, int rows, int column, int row, float bezel_x = 0, float bezel_y = 0) {
    params::Params p;
    p.set(ParamId::wall_columns, columns, ParamSource::Config);
    p.set(ParamId::wall_rows, rows, ParamSource::Config);
    p.set(ParamId::wall_column, column, ParamSource::Config);
    p.set(ParamId::wall_row, row, ParamSource::Config);
    p.set(ParamId::wall_bezel_x, bezel_x, ParamSource::Config);
    p.set(ParamId::wall_bezel_y, bezel_y, ParamSource::Config);
    return p;
}

void expect_window(const ViewWindow& w, glm::vec2 origin, glm::vec2 extent) {
    EXPECT_NEAR(w.origin.x, origin.x, 1e-6);
    EXPECT_NEAR(w.origin.y, origin.y, 1e-6);
    EXPECT_NEAR(w.extent.x, extent.x, 1e-6);
    EXPECT_NEAR(w.extent.y, extent.y, 1e-6);
}

TEST(ViewWindow, SingleScreenShowsTheWholeView) {
    expect_window(wall_window(params::Params{}, {1920, 1080}), {0, 0}, {1, 1});
    EXPECT_FLOAT_EQ(ViewWindow{}.view_aspect({1920, 1080}), 1920.0f / 1080.0f);
}

// Pixel (x, y) of a tile (rows of pixels from the top) sees what pixel (x, y) + the tile's offset of the
// whole view sees: both at the same place of the view, in fractions of it.
TEST(ViewWindow, TilePixelsAreTheWholeViewsPixelsPlusTheTileOffset) {
    const glm::vec2 screen{1920, 1080}, bezel{38, 40};
    const glm::vec2 whole = 3.0f * screen + 2.0f * bezel;  // a 3x3 wall
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            const ViewWindow w = wall_window(wall(3, 3, column, row, bezel.x, bezel.y), screen);
            const glm::vec2 offset = glm::vec2(column, row) * (screen + bezel);  // from the top left
            for (const glm::vec2 pixel : {glm::vec2(0, 0), glm::vec2(1919, 1079), glm::vec2(700, 300)}) {
                const glm::vec2 centre = pixel + 0.5f;
                // Where the tile puts this pixel (its v_uv: bottom-up) and where the whole view has it.
                const glm::vec2 in_tile =
                    w.origin + w.extent * glm::vec2(centre.x, screen.y - centre.y) / screen;
                const glm::vec2 in_whole =
                    glm::vec2(offset.x + centre.x, whole.y - (offset.y + centre.y)) / whole;
                EXPECT_NEAR(in_tile.x, in_whole.x, 1e-6) << column << ", " << row;
                EXPECT_NEAR(in_tile.y, in_whole.y, 1e-6) << column << ", " << row;
            }
            EXPECT_NEAR(w.view_size(glm::ivec2(screen)).x, whole.x, 1e-2);
            EXPECT_NEAR(w.view_size(glm::ivec2(screen)).y, whole.y, 1e-2);
            EXPECT_NEAR(w.view_aspect(glm::ivec2(screen)), whole.x / whole.y, 1e-5);
        }
}

TEST(ViewWindow, TopRowIsAtTheTopOfTheView) {
    expect_window(wall_window(wall(2, 2, 0, 0), {96, 64}), {0, 0.5f}, {0.5f, 0.5f});
    expect_window(wall_window(wall(2, 2, 1, 1), {96, 64}), {0.5f, 0}, {0.5f, 0.5f});
}

TEST(ViewWindow, MirrorModeShowsTheWholeViewOnEveryScreen) {
    params::Params p = wall(2, 2, 1, 0, 20, 20);
    p.set<ParamId::wall_mode>(params::WallMode::mirror, ParamSource::Config);
    expect_window(wall_window(p, {96, 64}), {0, 0}, {1, 1});
}

// A knob or the broker may set a column past the wall: the last column is shown, never a window outside.
TEST(ViewWindow, PositionPastTheWallIsClampedToTheLastTile) {
    expect_window(wall_window(wall(2, 3, 5, 7), {96, 64}), {0.5f, 0}, {0.5f, 1.0f / 3});
}

}  // namespace
}  // namespace puddle::render
