// --screenshot FILE writes what the name says: a JPEG for .jpg/.jpeg, a PNG otherwise, with the real
// binary, compared with each other pixel by pixel (JPEG is lossy: close, not equal).
#include "app/screenshot_file.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

using app::ScreenshotFormat;

TEST(ScreenshotFile, TheNameChoosesTheFormat) {
    EXPECT_EQ(app::screenshot_format("rain.jpg"), ScreenshotFormat::jpeg);
    EXPECT_EQ(app::screenshot_format("/tmp/Rain.JPEG"), ScreenshotFormat::jpeg);
    EXPECT_EQ(app::screenshot_format("rain.png"), ScreenshotFormat::png);
    EXPECT_EQ(app::screenshot_format("rain"), ScreenshotFormat::png);
    EXPECT_EQ(app::screenshot_format("jpg"), ScreenshotFormat::png);  // a name, not an extension
    EXPECT_EQ(app::screenshot_format("rain.jpg.png"), ScreenshotFormat::png);
}

TEST(ScreenshotFile, AJpgNameGetsAJpegOfTheSamePictureAsThePng) {
    TempDir dir;
    const std::string run = "-b headless --size 96x54 --frames 20 --seed 3 --screenshot ";
    const std::string png = (dir / "rain.png").string(), jpeg = (dir / "rain.JPG").string();
    const CommandResult a = run_puddle(run + png), b = run_puddle(run + jpeg);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const std::string bytes = read_file(jpeg);
    ASSERT_GE(bytes.size(), 3u);
    EXPECT_EQ(bytes.substr(0, 3), std::string("\xFF\xD8\xFF", 3)) << "a JPEG starts with SOI and a marker";
    EXPECT_EQ(read_file(png).substr(1, 3), "PNG");
    auto ip = assets::read_image(png), ij = assets::read_image(jpeg);
    ASSERT_TRUE(ip.ok() && ij.ok());
    ASSERT_EQ(ij->width, 96);
    ASSERT_EQ(ij->height, 54);
    // JPEG at quality 85 with 4:2:0 chroma on a 96x54 picture of small lit windows: measured 4.7 of 255
    // (alpha included, no pixel off by more than 44); the sky turned by 1.5 rad differs by 23, so "the
    // same frame" is checked.
    const std::string other = (dir / "other.png").string();
    const CommandResult c = run_puddle(
        "-b headless --size 96x54 --frames 20 --seed 3 --set environment.rotation=1.5 --screenshot " + other);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    auto io = assets::read_image(other);
    ASSERT_TRUE(io.ok());
    const ImageDiff d = compare_images(*ip, *ij, 48), turned = compare_images(*ip, *io, 48);
    EXPECT_LT(d.mean_abs_diff, 8.0) << "the same frame, through JPEG at quality 85";
    EXPECT_LT(d.fraction_over, 0.02);
    EXPECT_GT(d.mean_abs_diff, 0.0) << "lossy: a file identical to the PNG would not be a JPEG";
    EXPECT_GT(turned.mean_abs_diff, 3 * d.mean_abs_diff) << "another picture must differ more";
    std::printf("screenshot: JPEG against PNG %.2f of 255, the sky turned %.2f\n", d.mean_abs_diff,
                turned.mean_abs_diff);
}

TEST(ScreenshotFile, AnUnwritablePlaceIsOneLineAndExitCodeNotACrash) {
    const CommandResult r = run_puddle("-b headless --size 32x18 --frames 2 --screenshot /proc/no/rain.jpg");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("image: /proc/no/rain.jpg: cannot write"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace puddle::test
