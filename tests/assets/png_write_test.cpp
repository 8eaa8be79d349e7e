// Writing PNG files (write_png in assets/image_io.hpp, implemented in png_write.cpp): only non-empty
// RGBA8 images, through a temporary file renamed into place, so a failed write leaves nothing half
// written and no temporary behind. The round trip through read_image: image_io_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

class PngWriteTest : public ::testing::Test {
protected:
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    test::TempDir dir_;
};

Image pattern(int w, int h) {
    Image img = Image::make(w, h);
    for (std::size_t i = 0; i < img.data.size(); ++i) img.data[i] = static_cast<std::uint8_t>(i * 7);
    return img;
}

TEST_F(PngWriteTest, WriteIntoMissingFolderFailsAndLeavesNothing) {
    const std::string target = path("missing/out.png");
    auto written = write_png(target, pattern(2, 2));
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().code, ExitCode::Asset);
    EXPECT_EQ(written.error().message.rfind("image: " + target + ": cannot write: ", 0), 0u)
        << written.error().message;
    EXPECT_FALSE(fs::exists(target));
}

TEST_F(PngWriteTest, WriteRejectsFloatAndEmptyImages) {
    const auto f = write_png(path("f.png"), Image::make(2, 2, PixelFormat::RGBA32F));
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().code, ExitCode::Asset);
    EXPECT_EQ(f.error().message,
              "image: " + path("f.png") + ": cannot write: only non-empty RGBA8 images are written as PNG");
    EXPECT_FALSE(write_png(path("e.png"), Image{}).ok());
    EXPECT_FALSE(fs::exists(path("f.png")));
}

// A write over an existing picture replaces it whole: the smaller image is what reads back.
TEST_F(PngWriteTest, AnExistingFileIsReplacedWhole) {
    ASSERT_TRUE(write_png(path("shot.png"), pattern(37, 21)).ok());
    const Image small = pattern(3, 2);
    ASSERT_TRUE(write_png(path("shot.png"), small).ok());
    auto read = read_image(path("shot.png"));
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->width, 3);
    EXPECT_EQ(read->height, 2);
    EXPECT_EQ(read->data, small.data);
    EXPECT_FALSE(fs::exists(path("shot.png.tmp")));
}

// The rename fails when the target is a folder that holds something: the error names the path, the folder
// is untouched and the temporary file is removed (fails if it were left behind).
TEST_F(PngWriteTest, AFailedRenameLeavesNoTemporaryFileBehind) {
    fs::create_directories(dir_ / "shot.png" / "inside");
    auto written = write_png(path("shot.png"), pattern(4, 4));
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().code, ExitCode::Asset);
    EXPECT_EQ(written.error().message.rfind("image: " + path("shot.png") + ": cannot write: ", 0), 0u)
        << written.error().message;
    EXPECT_FALSE(fs::exists(path("shot.png.tmp")));
    EXPECT_TRUE(fs::is_directory(dir_ / "shot.png" / "inside"));
}

}  // namespace
}  // namespace puddle::assets
