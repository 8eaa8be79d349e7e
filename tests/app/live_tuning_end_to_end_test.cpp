// Live tuning through the real binary: a knob turned through the mock GPIO backend changes the
// parameter, the picture and the saved state; an edited config or SIGHUP reloads a running display.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "assets/image_io.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr const char* knob_config = R"(
[[knob]]
kind = "encoder"
a = 17
b = 18
param = "look.vignette"
step = 0.2
)";

// Rest levels, then (next frame, after the knob opened) four clockwise detents.
std::string turn_script(int detents) {
    std::string s = "gpiochip0 17 1\ngpiochip0 18 1\nwait 0\n";
    for (int i = 0; i < detents; ++i) s += "gpiochip0 17 0\ngpiochip0 18 0\ngpiochip0 17 1\ngpiochip0 18 1\n";
    return s;
}

TEST(LiveTuningEndToEnd, TurningAKnobChangesTheParameterThePictureAndTheSavedState) {
    TempDir dir;
    const std::string config = dir.write("puddle.toml", knob_config);
    const std::string still = dir.write("still.txt", turn_script(0));
    const std::string turned = dir.write("turned.txt", turn_script(4));
    const std::string common = "-b headless --size 160x90 --frames 20 --seed 3 --config " + config;

    const auto still_run =
        run_puddle(common + " --gpio mock:" + still + " --state " + (dir / "s0.toml").string() +
                   " --screenshot " + (dir / "still.png").string());
    ASSERT_EQ(still_run.exit_code, 0) << still_run.output;
    const auto turned_run =
        run_puddle(common + " --gpio mock:" + turned + " --state " + (dir / "s1.toml").string() +
                   " --screenshot " + (dir / "turned.png").string());
    ASSERT_EQ(turned_run.exit_code, 0) << turned_run.output;
    EXPECT_NE(turned_run.output.find("knob: look.vignette 0.5 -> 1.3 (knob)"), std::string::npos)
        << turned_run.output;

    auto a = assets::read_image((dir / "still.png").string());
    auto b = assets::read_image((dir / "turned.png").string());
    ASSERT_TRUE(a.ok() && b.ok());
    // More vignette: darker corners, the same centre.
    EXPECT_LT(mean_luma(*b, 0, 0, 16, 9) + 2.0, mean_luma(*a, 0, 0, 16, 9));
    EXPECT_NEAR(mean_luma(*b, 70, 40, 90, 50), mean_luma(*a, 70, 40, 90, 50), 3.0);

    EXPECT_FALSE(std::filesystem::exists(dir / "s0.toml")) << "nothing turned, nothing saved";
    const std::string state = read_file(dir / "s1.toml");
    EXPECT_NE(state.find("[look]\nvignette = 1.3"), std::string::npos) << state;

    // The next start restores it.
    const auto restored =
        run_puddle("--config " + config + " --state " + (dir / "s1.toml").string() + " --print-config");
    ASSERT_EQ(restored.exit_code, 0);
    EXPECT_NE(restored.output.find("look.vignette              = 1.3                      # knob"),
              std::string::npos)
        << restored.output;
}

TEST(LiveTuningEndToEnd, ARunningDisplayReloadsAnEditedConfigAndSurvivesABadOne) {
    TempDir dir;
    const std::string config = dir.write("puddle.toml", "[rain]\ndrop_count = 10\n");
    Running puddle({"-b", "headless", "--size", "64x36", "--frames", "0", "--config", config},
                   dir / "log.txt");
    ASSERT_TRUE(puddle.ok());
    ASSERT_TRUE(puddle.wait_for("headless: EGL")) << puddle.log();  // watching, and running frames now

    // An editor's save: a new file renamed over the old one.
    std::filesystem::rename(dir.write("puddle.toml.new", "[rain]\ndrop_count = 40\n"), config);
    ASSERT_TRUE(puddle.wait_for("config: reloaded: rain.drop_count 10 -> 40 (config)")) << puddle.log();

    std::ofstream(config) << "[rain]\ndrop_count = 400\n";  // out of range
    ASSERT_TRUE(puddle.wait_for("keeping the last good configuration")) << puddle.log();
    EXPECT_NE(puddle.log().find("puddle.toml:2: rain.drop_count = 400"), std::string::npos) << puddle.log();

    // SIGHUP reloads too (a valid file again).
    { std::ofstream(config) << "[rain]\ndrop_count = 12\n"; }
    ASSERT_TRUE(puddle.wait_for("rain.drop_count 40 -> 12")) << puddle.log();
    EXPECT_EQ(puddle.count("wave: 256x256 field"), 1) << "reloads did not restart the ripples";
    const int reloads = puddle.count("config: reloaded");
    puddle.signal(SIGHUP);
    ASSERT_TRUE(puddle.wait_for("config: reloaded", reloads)) << puddle.log();

    // A value that needs new textures: the wave field is rebuilt at the new size and frames go on.
    std::ofstream(config) << "[rain]\ndrop_count = 12\n[wave]\nresolution = 128\n";
    ASSERT_TRUE(puddle.wait_for("wave: 128x128 field")) << puddle.log();
    EXPECT_EQ(puddle.count("error"), 1) << "only the bad file's line:\n" << puddle.log();
    EXPECT_EQ(puddle.stop(), 0) << puddle.log();
}

// /etc/puddle/puddle.toml -> /opt/signage/puddle.toml: edits of the target and a re-pointed link reload.
TEST(LiveTuningEndToEnd, ASymlinkedConfigReloadsWhenItsTargetIsEditedOrTheLinkRepointed) {
    TempDir dir;
    std::filesystem::create_directories(dir / "etc");
    std::filesystem::create_directories(dir / "opt");
    dir.write("opt/day.toml", "[rain]\ndrop_count = 10\n");
    dir.write("opt/night.toml", "[rain]\ndrop_count = 30\n");
    const auto link = dir / "etc/puddle.toml";
    std::filesystem::create_symlink("../opt/day.toml", link);
    Running puddle({"-b", "headless", "--size", "64x36", "--frames", "0", "--config", link.string()},
                   dir / "log.txt");
    ASSERT_TRUE(puddle.ok());
    ASSERT_TRUE(puddle.wait_for("headless: EGL")) << puddle.log();

    std::ofstream(dir / "opt/day.toml") << "[rain]\ndrop_count = 20\n";
    ASSERT_TRUE(puddle.wait_for("config: reloaded: rain.drop_count 10 -> 20 (config)")) << puddle.log();
    const std::string repoint = "ln -sfn '" + (dir / "opt/night.toml").string() + "' '" + link.string() + "'";
    ASSERT_EQ(std::system(repoint.c_str()), 0);
    ASSERT_TRUE(puddle.wait_for("config: reloaded: rain.drop_count 20 -> 30 (config)")) << puddle.log();
    std::ofstream(dir / "opt/night.toml") << "[rain]\ndrop_count = 31\n";
    ASSERT_TRUE(puddle.wait_for("rain.drop_count 30 -> 31")) << puddle.log();
    EXPECT_EQ(puddle.stop(), 0) << puddle.log();
}

TEST(LiveTuningEndToEnd, AMissingGpioChipIsAWarningNotAFailure) {
    TempDir dir;
    const std::string config = dir.write("puddle.toml", std::string(knob_config) + "chip = \"gpiochip9\"\n");
    const auto r = run_puddle("-b headless --size 64x36 --frames 3 --gpio mock: --config " + config);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("gpio: gpiochip9 line 17: no such chip or line"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("retrying every 3 s"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace puddle::test
