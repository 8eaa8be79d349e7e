// Cube crosses: both layouts give back the six faces they were made from, upright, in GL order; sizes
// that do not divide into square faces are named with the path and what was expected.
#include "assets/cube_cross.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>

namespace puddle::assets {
namespace {

constexpr int kFace = 8;

// Face i: a flat colour of its own with one marker pixel at its top-left corner, so turns and flips show.
Image marked_face(std::size_t i) {
    Image img = Image::make(kFace, kFace);
    for (int y = 0; y < kFace; ++y)
        for (int x = 0; x < kFace; ++x) {
            std::uint8_t* p = img.pixel8(x, y);
            p[0] = static_cast<std::uint8_t>(40 * i), p[1] = 100,
            p[2] = static_cast<std::uint8_t>(250 - 40 * i), p[3] = 255;
        }
    img.pixel8(0, 0)[1] = 255;
    return img;
}

void paste(Image& dst, const Image& face, int column, int row, bool upside_down) {
    for (int y = 0; y < kFace; ++y)
        for (int x = 0; x < kFace; ++x) {
            const int sx = upside_down ? kFace - 1 - x : x, sy = upside_down ? kFace - 1 - y : y;
            std::memcpy(dst.pixel8(column * kFace + x, row * kFace + y), face.pixel8(sx, sy), 4);
        }
}

// Made independently of the loader, from the layouts in cube_cross.hpp.
Image make_cross(bool horizontal) {
    Image cross = Image::make(horizontal ? 4 * kFace : 3 * kFace, horizontal ? 3 * kFace : 4 * kFace);
    paste(cross, marked_face(0), 2, 1, false);  // +X
    paste(cross, marked_face(1), 0, 1, false);  // -X
    paste(cross, marked_face(2), 1, 0, false);  // +Y
    paste(cross, marked_face(3), 1, 2, false);  // -Y
    paste(cross, marked_face(4), 1, 1, false);  // +Z
    if (horizontal)
        paste(cross, marked_face(5), 3, 1, false);  // -Z
    else
        paste(cross, marked_face(5), 1, 3, true);  // -Z, below -Y and upside down
    return cross;
}

void expect_faces_are_the_originals(const CubeImages& cube) {
    for (std::size_t i = 0; i < 6; ++i) {
        ASSERT_EQ(cube.faces[i].width, kFace);
        ASSERT_EQ(cube.faces[i].height, kFace);
        EXPECT_EQ(cube.faces[i].data, marked_face(i).data) << cube_face_names[i];
    }
}

TEST(CubeCross, ProportionsPickTheLayout) {
    EXPECT_EQ(cross_layout(4096, 3072), CrossLayout::Horizontal);
    EXPECT_EQ(cross_layout(1022, 768), CrossLayout::Horizontal);  // close enough to be meant as one
    EXPECT_EQ(cross_layout(768, 1024), CrossLayout::Vertical);
    EXPECT_EQ(cross_layout(2048, 1024), CrossLayout::None);
    EXPECT_EQ(cross_layout(512, 512), CrossLayout::None);
}

TEST(CubeCross, HorizontalCrossGivesTheSixFacesUpright) {
    const Image cross = make_cross(true);
    auto cube = split_cube_cross(cross, CrossLayout::Horizontal, "h.png");
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->source, "h.png");
    expect_faces_are_the_originals(*cube);
}

TEST(CubeCross, VerticalCrossTurnsTheBackFaceUpright) {
    const Image cross = make_cross(false);
    auto cube = split_cube_cross(cross, CrossLayout::Vertical, "v.png");
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    expect_faces_are_the_originals(*cube);
}

TEST(CubeCross, FloatCrossKeepsItsValues) {
    Image cross = Image::make(4 * kFace, 3 * kFace, PixelFormat::RGBA32F);
    cross.pixelf(2 * kFace + 3, kFace + 5)[0] = 42.5f;  // inside +X
    auto cube = split_cube_cross(cross, CrossLayout::Horizontal, "h.exr");
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->faces[0].format, PixelFormat::RGBA32F);
    EXPECT_EQ(cube->faces[0].pixelf(3, 5)[0], 42.5f);
}

TEST(CubeCross, SizeThatDoesNotDivideNamesThePathAndTheRule) {
    const Image cross = Image::make(1022, 768);
    auto cube = split_cube_cross(cross, CrossLayout::Horizontal, "/sky/cross.png");
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(
        cube.error().message,
        "environment.image: /sky/cross.png is 1022x768: a horizontal cube cross must be 4 square faces wide "
        "and 3 high (e.g. 1024x768)");
    auto vertical = split_cube_cross(Image::make(300, 401), CrossLayout::Vertical, "v.png");
    ASSERT_FALSE(vertical.ok());
    EXPECT_EQ(
        vertical.error().message,
        "environment.image: v.png is 300x401: a vertical cube cross must be 3 square faces wide and 4 high "
        "(e.g. 768x1024)");
}

}  // namespace
}  // namespace puddle::assets
