// The binary with a mock camera (`--camera mock:PATH`): it reflects the known image, the right way round.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include "assets/image_io.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"

namespace puddle::test {
namespace {

// Mean of one channel over a rectangle.
double mean_channel(const assets::Image& img, int c, int x0, int y0, int x1, int y1) {
    double sum = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += img.pixel8(x, y)[c];
    return sum / double((x1 - x0) * (y1 - y0));
}

// A room seen by the camera: red on the left half, blue on the right.
std::string write_room(const TempDir& dir) {
    assets::Image room = assets::Image::make(64, 36);
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            std::uint8_t* p = room.pixel8(x, y);
            p[0] = x < 32 ? 230 : 20;
            p[1] = 20;
            p[2] = x < 32 ? 20 : 230;
            p[3] = 255;
        }
    const std::string path = (dir / "room.png").string();
    EXPECT_TRUE(assets::write_png(path, room));
    return path;
}

TEST(CameraEndToEnd, MockCameraIsReflectedTheRightWayRound) {
    TempDir dir;
    const std::string room = write_room(dir);
    const std::string with = (dir / "camera.png").string(), without = (dir / "sky.png").string();
    const std::string common = "-b headless --size 160x90 --frames 8 --seed 3 ";
    const CommandResult a = run_puddle(common + "--camera mock:" + room + " --screenshot " + with);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    EXPECT_NE(a.output.find("camera: streaming mock:" + room), std::string::npos) << a.output;
    ASSERT_EQ(run_puddle(common + "--screenshot " + without).exit_code, 0);
    auto cam = assets::read_image(with), sky = assets::read_image(without);
    ASSERT_TRUE(cam && sky);
    EXPECT_TRUE(assets::write_png((output_dir() / "camera_end_to_end.png").string(), *cam));

    // The water in the middle of the picture reflects the room: left of centre red, right of it blue.
    const int y0 = 35, y1 = 65;
    const double left_red = mean_channel(*cam, 0, 30, y0, 70, y1),
                 left_blue = mean_channel(*cam, 2, 30, y0, 70, y1);
    const double right_red = mean_channel(*cam, 0, 90, y0, 130, y1),
                 right_blue = mean_channel(*cam, 2, 90, y0, 130, y1);
    EXPECT_GT(left_red, left_blue + 15) << "left " << left_red << " red, " << left_blue << " blue";
    EXPECT_GT(right_blue, right_red + 15) << "right " << right_red << " red, " << right_blue << " blue";
    // Without the camera the same water shows the night sky: no such colours.
    const double sky_left_red = mean_channel(*sky, 0, 30, y0, 70, y1),
                 sky_left_blue = mean_channel(*sky, 2, 30, y0, 70, y1);
    EXPECT_LT(sky_left_red, sky_left_blue + 5);
}

TEST(CameraEndToEnd, BlendZeroLooksLikeTheCubemap) {
    TempDir dir;
    const std::string room = write_room(dir);
    const std::string with = (dir / "blend0.png").string(), without = (dir / "sky.png").string();
    // An 8-bit copy of the night sky: the camera's cube is 8-bit and clips the HDR sky's windows at white
    // (a documented limit), and this is about the resampling.
    std::filesystem::create_directory(dir / "sky");
    const std::string sky = write_ldr_night_sky((dir / "sky").string());
    const std::string common =
        "-b headless --size 160x90 --frames 4 --seed 3 --set environment.image=" + sky + " ";
    ASSERT_EQ(run_puddle(common + "--camera mock:" + room +
                         " --set environment.camera_blend=0 --screenshot " + with)
                  .exit_code,
              0);
    ASSERT_EQ(run_puddle(common + "--screenshot " + without).exit_code, 0);
    auto a = assets::read_image(with), b = assets::read_image(without);
    ASSERT_TRUE(a && b);
    // The camera cube resamples the sky at 256 per face: close, not bit-identical.
    const ImageDiff d = compare_images(*a, *b, 16);
    EXPECT_LT(d.mean_abs_diff, 1.5);
    EXPECT_LT(d.fraction_over, 0.01);
}

TEST(CameraEndToEnd, MissingMockImageExitsThree) {
    const CommandResult r = run_puddle("-b headless --frames 1 --camera mock:/nonexistent/room.png");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/room.png"), std::string::npos) << r.output;
}

// The device is opened on the camera worker, so the warning comes from the frame that collects its
// answer: run until it is logged rather than for a fixed number of frames.
TEST(CameraEndToEnd, NoCameraDeviceWarnsAndRendersTheCubemap) {
    TempDir dir;
    Running puddle(
        {"-b", "headless", "--size", "96x54", "--frames", "0", "--camera", "/dev/puddle-no-such-camera"},
        dir / "log.txt");
    EXPECT_TRUE(puddle.wait_for(
        "camera: /dev/puddle-no-such-camera: open: No such file or directory; reflecting the cubemap"))
        << puddle.log();
    EXPECT_EQ(puddle.stop(), 0) << puddle.log();
}

}  // namespace
}  // namespace puddle::test
