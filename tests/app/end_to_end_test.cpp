// The real binary, as a person runs it: renders a PNG headless, and fails clearly on bad input.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

struct Outcome {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

Outcome run_puddle(const std::string& args) {
    const std::string cmd = std::string(PUDDLE_BINARY) + " " + args + " 2>&1";
    Outcome r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

TEST(EndToEnd, RendersAPngHeadlessAndExitsZero) {
    TempDir dir;
    const std::string png = (dir / "out.png").string();
    const Outcome r = run_puddle("--backend headless --size 200x120 --frames 20 --screenshot " + png);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    auto image = assets::read_image(png);
    ASSERT_TRUE(image.ok()) << image.error().message;
    EXPECT_EQ(image->width, 200);
    EXPECT_EQ(image->height, 120);
    EXPECT_GT(luma_stddev(*image, 0, 0, 200, 120), 3.0) << "a picture, not a flat fill";
    EXPECT_NE(r.output.find(png), std::string::npos) << "says where the PNG went:\n" << r.output;
}

TEST(EndToEnd, SameCommandLineGivesTheSameImage) {
    TempDir dir;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string();
    ASSERT_EQ(run_puddle("-b headless --size 96x54 --frames 30 --seed 4 --screenshot " + a).exit_code, 0);
    ASSERT_EQ(run_puddle("-b headless --size 96x54 --frames 30 --seed 4 --screenshot " + b).exit_code, 0);
    auto ia = assets::read_image(a), ib = assets::read_image(b);
    ASSERT_TRUE(ia.ok() && ib.ok());
    EXPECT_EQ(compare_images(*ia, *ib, 0).max_channel_diff, 0);
}

TEST(EndToEnd, BadConfigExitsTwoNamingFileLineAndRange) {
    TempDir dir;
    const std::string cfg = dir.write("bad.toml", "[rain]\ndrop_count = 10\nintensity = 9.5\n");
    const Outcome r = run_puddle("-b headless --frames 1 --config " + cfg);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(cfg + ":3"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("rain.intensity"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("from 0 to 4"), std::string::npos) << r.output;
}

TEST(EndToEnd, UnknownKeySuggestsTheNearestOne) {
    TempDir dir;
    const std::string cfg = dir.write("typo.toml", "[water]\nturbidty = 0.1\n");
    const Outcome r = run_puddle("-b headless --frames 1 --config " + cfg);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find(cfg + ":2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("did you mean 'water.turbidity'"), std::string::npos) << r.output;
}

TEST(EndToEnd, BadSetValueExitsTwo) {
    const Outcome r = run_puddle("-b headless --frames 1 --set wave.damping=2");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("wave.damping"), std::string::npos) << r.output;
}

TEST(EndToEnd, MissingImageExitsThreeNamingThePath) {
    const Outcome r = run_puddle("-b headless --frames 1 --set ground.image=/nonexistent/paving.jpg");
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/paving.jpg"), std::string::npos) << r.output;
}

TEST(EndToEnd, EnvironmentOfTheWrongShapeExitsThreeNamingPathAndShape) {
    TempDir dir;
    const std::string wide = (dir / "wide.png").string(), cross = (dir / "cross.png").string();
    ASSERT_TRUE(assets::write_png(wide, assets::Image::make(300, 200)).ok());
    ASSERT_TRUE(assets::write_png(cross, assets::Image::make(1022, 768)).ok());
    const Outcome panorama = run_puddle("-b headless --frames 1 --set environment.image=" + wide);
    EXPECT_EQ(panorama.exit_code, 3) << panorama.output;
    EXPECT_NE(panorama.output.find(wide + " is 300x200: expected an equirectangular panorama twice as wide as high"),
              std::string::npos)
        << panorama.output;
    const Outcome bad_cross = run_puddle("-b headless --frames 1 --set environment.image=" + cross);
    EXPECT_EQ(bad_cross.exit_code, 3) << bad_cross.output;
    EXPECT_NE(bad_cross.output.find(cross + " is 1022x768: a horizontal cube cross must be 4 square faces wide"),
              std::string::npos)
        << bad_cross.output;
}

TEST(EndToEnd, HelpAndListParamsTeach) {
    const Outcome help = run_puddle("--help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--screenshot"), std::string::npos);
    EXPECT_NE(help.output.find("Exit codes"), std::string::npos);
    const Outcome list = run_puddle("--list-params");
    EXPECT_EQ(list.exit_code, 0);
    EXPECT_NE(list.output.find("rain.drop_count"), std::string::npos);
    EXPECT_NE(list.output.find("water.turbidity"), std::string::npos);
}

}  // namespace
}  // namespace puddle::test
