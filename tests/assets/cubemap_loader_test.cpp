#include "assets/cubemap_loader.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "assets/image_io.hpp"
#include "support/image_bomb.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

struct Rgb {
    std::uint8_t r, g, b;
};
// One distinct colour per face, in GL order.
constexpr std::array<Rgb, 6> kFaceColours{
    {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {200, 200, 30}, {30, 200, 200}, {200, 30, 200}}};

Image solid(int w, int h, Rgb c) {
    Image img = Image::make(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel8(x, y);
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
            p[3] = 255;
        }
    }
    return img;
}

// Any format OIIO writes, chosen by the extension (write_png only makes PNGs).
void write_any(const std::string& path, const Image& img) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    const OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, img.data.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

class CubemapLoaderTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               (std::string("puddle-cubemap-") + info->name() + "-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // Six faces of `size`, as PNG except -Y (TIFF), +Z (upper-case JPG) and -Z (.jpeg).
    void write_faces(int w, int h) {
        const std::array<std::string, 6> names{"px.png", "nx.png", "py.png", "ny.tif", "pz.JPG", "nz.jpeg"};
        for (std::size_t i = 0; i < 6; ++i) {
            const Image img = solid(w, h, kFaceColours[i]);
            if (names[i].ends_with(".png")) {
                ASSERT_TRUE(write_png(path(names[i]), img).ok());
            } else {
                write_any(path(names[i]), img);
            }
        }
    }

    fs::path dir_;
};

TEST_F(CubemapLoaderTest, FolderOfMixedFormatsLoadsInGlOrder) {
    write_faces(16, 16);
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->source, dir_.string());
    for (std::size_t i = 0; i < 6; ++i) {
        const Image& face = cube->faces[i];
        ASSERT_EQ(face.width, 16) << cube_face_names[i];
        ASSERT_EQ(face.height, 16) << cube_face_names[i];
        ASSERT_EQ(face.format, PixelFormat::RGBA8);
        const std::uint8_t* p = face.pixel8(8, 8);
        // JPEG is lossy even for a flat colour; the others are exact.
        const int tolerance = i >= 4 ? 3 : 0;
        EXPECT_NEAR(p[0], kFaceColours[i].r, tolerance) << cube_face_names[i];
        EXPECT_NEAR(p[1], kFaceColours[i].g, tolerance) << cube_face_names[i];
        EXPECT_NEAR(p[2], kFaceColours[i].b, tolerance) << cube_face_names[i];
        EXPECT_EQ(p[3], 255) << cube_face_names[i];
    }
}

TEST_F(CubemapLoaderTest, PngIsPreferredWhenAFaceExistsTwice) {
    write_faces(8, 8);
    ASSERT_TRUE(write_png(path("ny.png"), solid(8, 8, {1, 2, 3})).ok());  // beside ny.tif
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->faces[3].pixel8(0, 0)[0], 1);
}

TEST_F(CubemapLoaderTest, MissingFaceNamesTheFaceAndTheFolder) {
    write_faces(8, 8);
    fs::remove(path("ny.tif"));
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(
        cube.error().message,
        "cubemap: " + dir_.string() +
            ": no face image for 'ny' (looked for ny.png, ny.jpg, ny.jpeg, ny.hdr, ny.exr, ny.tif, ny.tiff, "
            "ny.bmp, ny.tga, ny.webp)");
}

TEST_F(CubemapLoaderTest, FaceOfAnotherSizeNamesBothFiles) {
    write_faces(16, 16);
    ASSERT_TRUE(write_png(path("nx.png"), solid(8, 8, kFaceColours[1])).ok());
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(cube.error().message,
              "cubemap: " + path("nx.png") +
                  " is 8x8 but px.png is 16x16: all six faces must be square and the same size");
}

// Issue 15: every face's header is read before any face is decoded. -Z claims 16000x16000 over a few
// bytes; decoding the faces first allocated its 976 MiB and failed in the decoder instead.
TEST_F(CubemapLoaderTest, AFaceOfAnotherSizeIsRefusedFromItsHeaderWithoutDecoding) {
    write_faces(8, 8);
    fs::remove(path("nz.jpeg"));
    std::ofstream(path("nz.png"), std::ios::binary) << test::png_claiming(16000, 16000);
    const std::size_t peak_before = test::peak_rss_bytes();
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().message,
              "cubemap: " + path("nz.png") +
                  " is 16000x16000 but px.png is 8x8: all six faces must be square and the same size");
    EXPECT_LT(test::peak_rss_bytes() - peak_before, std::size_t{64} << 20) << "no pixel buffer was allocated";
}

TEST_F(CubemapLoaderTest, NonSquareFacesAreRejected) {
    write_faces(16, 8);
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(cube.error().message,
              "cubemap: " + path("px.png") + " is 16x8: all six faces must be square and the same size");
}

TEST_F(CubemapLoaderTest, UnreadableFaceReportsThatFile) {
    write_faces(8, 8);
    std::ofstream(path("py.png"), std::ios::binary) << "not a png";
    auto cube = load_cubemap_folder(dir_.string());
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(cube.error().message.rfind("image: " + path("py.png") + ": ", 0), 0u) << cube.error().message;
}

TEST_F(CubemapLoaderTest, MissingFolderIsAnError) {
    const std::string missing = path("no-such-sky");
    auto cube = load_cubemap_folder(missing);
    ASSERT_FALSE(cube.ok());
    EXPECT_EQ(cube.error().code, ExitCode::Asset);
    EXPECT_EQ(cube.error().message, "cubemap: " + missing + ": cannot open: No such file or directory");

    ASSERT_TRUE(write_png(path("px.png"), solid(2, 2, kFaceColours[0])).ok());
    auto file = load_cubemap_folder(path("px.png"));
    ASSERT_FALSE(file.ok());
    EXPECT_EQ(file.error().message, "cubemap: " + path("px.png") + ": not a folder");
}

TEST_F(CubemapLoaderTest, ExplicitPathsLoadInTheGivenOrder) {
    std::array<std::string, 6> paths;
    for (std::size_t i = 0; i < 6; ++i) {
        paths[i] = path("face" + std::to_string(i) + ".png");
        ASSERT_TRUE(write_png(paths[i], solid(4, 4, kFaceColours[i])).ok());
    }
    auto cube = load_cubemap_faces(paths);
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    EXPECT_EQ(cube->source, dir_.string());
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(cube->faces[i].pixel8(1, 1)[2], kFaceColours[i].b);

    ASSERT_TRUE(write_png(paths[5], solid(2, 2, kFaceColours[5])).ok());
    auto mismatched = load_cubemap_faces(paths);
    ASSERT_FALSE(mismatched.ok());
    EXPECT_NE(mismatched.error().message.find(paths[5] + " is 2x2 but face0.png is 4x4"), std::string::npos)
        << mismatched.error().message;
}

TEST(CubemapLoaderShared, SharedCubemapFolderLoads) {
    const std::string folder = PUDDLE_SHARED_DIR "/assets/cubemap";
    if (!fs::exists(folder)) GTEST_SKIP() << "shared cubemap not found at " << folder;
    auto cube = load_cubemap_folder(folder);
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    for (const Image& face : cube->faces) {
        EXPECT_EQ(face.width, 512);
        EXPECT_EQ(face.height, 512);
        EXPECT_EQ(face.data.size(), 512u * 512u * 4u);
    }
}

}  // namespace
}  // namespace puddle::assets
