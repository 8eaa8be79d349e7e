// GPU memory running out, for real, through the real binary: the process's address space is limited
// (ulimit -v at start-up, prlimit on a running display), so llvmpipe's glTexStorage2D of a big sky cube
// fails with GL_OUT_OF_MEMORY. Start-up stops with exit code 5 and one line naming the texture and its
// size; a live edit keeps the sky shown, or falls back to smaller faces that fit, with one line.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "assets/image_io.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr long mib = 1024;  // in KiB, the unit of /proc/PID/status and ulimit -v

// A 64x32 panorama: a bright sky over a darker ground, so a black reflection cannot pass for it.
std::string write_sky(const TempDir& dir) {
    assets::Image sky = assets::Image::make(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            std::uint8_t* p = &sky.data[(std::size_t(y) * 64 + std::size_t(x)) * 4];
            const bool above = y < 16;
            p[0] = above ? std::uint8_t(150 + y * 4) : 90;
            p[1] = above ? std::uint8_t(190 + y * 2) : 80;
            p[2] = above ? 250 : 60;
            p[3] = 255;
        }
    const std::string path = (dir / "sky.png").string();
    EXPECT_TRUE(assets::write_png(path, sky).ok());
    return path;
}

// Still water (no drops, no falling rain), so every frame shows the same picture whatever the time.
std::string still_config(const std::string& sky, int face_size) {
    return fmt::format(
        "[environment]\nimage = \"{}\"\nface_size = {}\n[rain]\nintensity = 0.0\n[overlay]\nrain = false\n",
        sky, face_size);
}

// "VmSize:" or "VmPeak:" of a running process, in KiB; 0 when unreadable.
long vm_kib(pid_t pid, const std::string& field) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.starts_with(field)) return std::stol(line.substr(field.size()));
    return 0;
}

int lines_starting(const std::string& log, const std::string& prefix) {
    int n = log.starts_with(prefix) ? 1 : 0;
    for (auto at = log.find("\n" + prefix); at != std::string::npos; at = log.find("\n" + prefix, at + 1))
        ++n;
    return n;
}

// Renders 10 frames of `config` to a PNG: the picture a display with that sky shows.
assets::Image reference_picture(const TempDir& dir, const std::string& config) {
    const std::string png = (dir / "reference.png").string();
    const auto r =
        run_puddle("-b headless --size 96x54 --frames 10 --config " + config + " --screenshot " + png);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    auto image = assets::read_image(png);
    EXPECT_TRUE(image.ok());
    return image.ok() ? std::move(image).value() : assets::Image{};
}

// Rewrites the config the way an editor saves: a new file renamed over the old one.
void edit(const TempDir& dir, const std::string& config, const std::string& text) {
    std::filesystem::rename(dir.write("puddle.toml.new", text), config);
}

// Starts a display on `config`, waits until it runs frames, then limits its address space to what it
// uses now plus `headroom_kib`: later allocations beyond that fail as on a machine out of memory.
void limit_when_running(Running& puddle, long headroom_kib) {
    ASSERT_TRUE(puddle.ok());
    ASSERT_TRUE(puddle.wait_for("started:")) << puddle.log();
    std::this_thread::sleep_for(std::chrono::seconds(1));  // a few frames: their shaders are built
    const long size = vm_kib(puddle.pid(), "VmSize:");
    ASSERT_GT(size, 0);
    const rlimit limit{static_cast<rlim_t>(size + headroom_kib) * 1024, RLIM_INFINITY};
    ASSERT_EQ(::prlimit(puddle.pid(), RLIMIT_AS, &limit, nullptr), 0);
}

TEST(GpuMemoryEndToEnd, ACubeThatDoesNotFitStopsStartUpWithExitCode5AndOneLine) {
    TempDir dir;
    const std::string sky = write_sky(dir);
    const std::string args = "-b headless --size 96x54 --frames 3 --set environment.image=" + sky;

    // The address space a run with a small cube needs at its peak, plus 128 MiB: a 4096 cube (512 MiB) cannot
    // fit.
    long peak = 0;
    {
        Running probe({"-b", "headless", "--size", "96x54", "--frames", "0", "--set",
                       "environment.image=" + sky, "--set", "environment.face_size=64"},
                      dir / "probe.log");
        ASSERT_TRUE(probe.wait_for("started:")) << probe.log();
        std::this_thread::sleep_for(std::chrono::seconds(1));
        peak = vm_kib(probe.pid(), "VmPeak:");
        EXPECT_EQ(probe.stop(), 0) << probe.log();
    }
    ASSERT_GT(peak, 0);
    auto run_limited = [&](int face_size) {
        return run_command(fmt::format("ulimit -v {} && exec {} {} --set environment.face_size={}",
                                       peak + 128 * mib, PUDDLE_BINARY, args, face_size));
    };
    const auto fits = run_limited(64);
    ASSERT_EQ(fits.exit_code, 0) << "the limit leaves room for a small cube:\n" << fits.output;

    const auto too_big = run_limited(4096);
    EXPECT_EQ(too_big.exit_code, 5) << too_big.output;
    EXPECT_NE(
        too_big.output.find("error: gpu: texture 'environment' (cube 6 x 4096x4096 SRGB8_ALPHA8, 13 levels, "
                            "512.0 MiB): glTexStorage2D: GL_OUT_OF_MEMORY"),
        std::string::npos)
        << too_big.output;
    EXPECT_EQ(lines_starting(too_big.output, "error: "), 1) << too_big.output;
    EXPECT_EQ(too_big.output.find("environment: " + sky), std::string::npos) << "not logged as loaded:\n"
                                                                             << too_big.output;
}

TEST(GpuMemoryEndToEnd, ALiveEditThatDoesNotFitKeepsTheSkyShownAndLogsOneLine) {
    TempDir dir;
    const std::string sky = write_sky(dir);
    const std::string config = dir.write("puddle.toml", still_config(sky, 1024));
    const assets::Image reference = reference_picture(dir, config);
    const std::string shown = (dir / "shown.png").string();

    Running puddle(
        {"-b", "headless", "--size", "96x54", "--frames", "0", "--config", config, "--screenshot", shown},
        dir / "log.txt");
    // 96 MiB free: neither 4096 (512 MiB) nor the fallback's 2048 (128 MiB) fits; 1024 is what is shown.
    limit_when_running(puddle, 96 * mib);
    edit(dir, config, still_config(sky, 4096));
    ASSERT_TRUE(puddle.wait_for("keeping")) << puddle.log();
    const std::string log = puddle.log();
    EXPECT_NE(
        log.find("error: gpu: texture 'environment' (cube 6 x 4096x4096 SRGB8_ALPHA8, 13 levels, 512.0 MiB): "
                 "glTexStorage2D: GL_OUT_OF_MEMORY; faces down to 2048x2048 did not fit either (keeping " +
                 sky + ")"),
        std::string::npos)
        << log;
    EXPECT_EQ(lines_starting(log, "error: "), 1) << log;
    EXPECT_EQ(lines_starting(log, "warning: "), 0) << log;
    ASSERT_EQ(puddle.stop(), 0) << puddle.log();

    auto after = assets::read_image(shown);
    ASSERT_TRUE(after.ok());
    const ImageDiff d = compare_images(*after, reference, 0);
    EXPECT_EQ(d.max_channel_diff, 0) << "the sky shown before the edit is still reflected";
}

TEST(GpuMemoryEndToEnd, ALiveEditThatDoesNotFitFallsBackToSmallerFacesThatDo) {
    TempDir dir;
    const std::string sky = write_sky(dir);
    const std::string config = dir.write("puddle.toml", still_config(sky, 128));
    const assets::Image reference = reference_picture(dir, config);
    const std::string shown = (dir / "shown.png").string();

    Running puddle(
        {"-b", "headless", "--size", "96x54", "--frames", "0", "--config", config, "--screenshot", shown},
        dir / "log.txt");
    // 96 MiB free: 2048 (128 MiB) does not fit, 1024 (32 MiB) does.
    limit_when_running(puddle, 96 * mib);
    edit(dir, config, still_config(sky, 2048));
    ASSERT_TRUE(puddle.wait_for("(1024x1024 faces")) << puddle.log();
    const std::string log = puddle.log();
    EXPECT_NE(
        log.find(
            "warning: gpu: texture 'environment' (cube 6 x 2048x2048 SRGB8_ALPHA8, 12 levels, 128.0 MiB): "
            "glTexStorage2D: GL_OUT_OF_MEMORY; using 1024x1024 faces instead"),
        std::string::npos)
        << log;
    EXPECT_EQ(lines_starting(log, "warning: "), 1) << log;
    EXPECT_EQ(lines_starting(log, "error: "), 0) << log;
    ASSERT_EQ(puddle.stop(), 0) << puddle.log();

    // The same sky from a bigger cube: a few levels apart where filtering differs, never a black reflection.
    auto after = assets::read_image(shown);
    ASSERT_TRUE(after.ok());
    const ImageDiff d = compare_images(*after, reference, 8);
    EXPECT_LT(d.mean_abs_diff, 2.0);
    EXPECT_EQ(d.fraction_over, 0.0);
}

}  // namespace
}  // namespace puddle::test
