// Video walls, with the real binary and the real clock: two `puddle` processes started seconds
// apart with wall.clock = "realtime" and the same --screenshot-at time write the same wave step, and their
// pictures match after the warm-up; a third, one second later, shows a different picture (so the match
// is not that of a flat field). Measured here (2 cores, llvmpipe, under load): mean channel difference
// 0.025 of 255 between the first two (what the later screen's shorter history leaves, no pixel off by more
// than 8), against 20 for the picture a second later. A screen that joined without the warm-up (a flat
// field at the clock's step) would show other ripples and fail.
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <string>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

// "wall: wave step N written to PATH" from a run's log; -1 when absent.
long long written_step(const std::string& log) {
    std::smatch m;
    static const std::regex line("wall: wave step ([0-9]+) written to");
    return std::regex_search(log, m, line) ? std::stoll(m[1]) : -1;
}

TEST(WallEndToEnd, TwoScreensStartedApartWriteTheSameStepAtTheSameWallTime) {
    TempDir dir;
    const std::string a = (dir / "a.png").string(), b = (dir / "b.png").string(),
                      c = (dir / "c.png").string();
    // The reference's small field keeps the warm-up (10 s of steps at 60 a frame) within a few seconds on
    // llvmpipe with three screens on two cores (the wall in the default field: WallInStep, in-process);
    // 10 s leaves 0.985^300 = 1e-2 of the later screen's start before the 5 s it runs on its own.
    const std::string common = std::string(PUDDLE_BINARY) +
                               " -b headless --size 160x90 --set wall.clock=realtime --set "
                               "wave.model=reference --set wave.resolution=128"
                               " --set wall.warmup=10 --log-level info";
    const long long now =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch())
            .count();
    const std::string at = std::to_string(now + 14), later = std::to_string(now + 15);
    // Screen A starts now, B and C three seconds later; their logs are kept apart.
    const std::string script = common + " --screenshot-at " + at + " --screenshot " + a + " > " +
                               (dir / "a.log").string() + " 2>&1 & pa=$!; sleep 3; " + common +
                               " --screenshot-at " + later + " --screenshot " + c + " > " +
                               (dir / "c.log").string() + " 2>&1 & pc=$!; " + common + " --screenshot-at " +
                               at + " --screenshot " + b + " > " + (dir / "b.log").string() +
                               " 2>&1; rb=$?; wait $pa; ra=$?; wait $pc; rc=$?; echo \"exit $ra $rb $rc\"";
    const CommandResult run = run_command(script);
    EXPECT_NE(run.output.find("exit 0 0 0"), std::string::npos) << run.output;
    const std::string log_a = read_file(dir / "a.log"), log_b = read_file(dir / "b.log"),
                      log_c = read_file(dir / "c.log");
    ASSERT_GT(written_step(log_a), 0) << log_a;
    EXPECT_EQ(written_step(log_a), written_step(log_b)) << log_a << log_b;
    EXPECT_EQ(written_step(log_c), written_step(log_a) + 60) << "one second later at 60 steps/s\n" << log_c;
    for (const std::string* log : {&log_a, &log_b, &log_c})
        EXPECT_EQ(log->find("not reached"), std::string::npos) << "the run fell behind the clock:\n" << *log;

    auto ia = assets::read_image(a), ib = assets::read_image(b), ic = assets::read_image(c);
    ASSERT_TRUE(ia.ok() && ib.ok() && ic.ok());
    const ImageDiff same = compare_images(*ia, *ib, 8);
    const ImageDiff next = compare_images(*ia, *ic, 8);
    EXPECT_LT(same.mean_abs_diff, 0.25) << "A and B at the same wall time";
    EXPECT_LT(same.fraction_over, 0.002);
    EXPECT_GT(next.mean_abs_diff, 4 * same.mean_abs_diff + 0.5) << "a second later the rain has moved on";
    (void)assets::write_png((output_dir() / "wall_two_processes_a.png").string(), *ia);
    (void)assets::write_png((output_dir() / "wall_two_processes_b.png").string(), *ib);
    std::printf(
        "wall, two processes 3 s apart: mean difference %.3f of 255 (%.4f of pixels over 8); "
        "one second later: %.3f\n",
        same.mean_abs_diff, same.fraction_over, next.mean_abs_diff);
}

TEST(WallEndToEnd, ABezelWiderThanTheScreenIsWarnedAboutOnceAndAUsualOneIsNot) {
    const std::string wall = "-b headless --size 64x36 --frames 3 --set wall.columns=2 --set wall.rows=2 ";
    const CommandResult huge = run_puddle(wall + "--set wall.bezel_x=100");
    EXPECT_EQ(huge.exit_code, 0) << huge.output;  // valid: the screen keeps running
    const std::string warning = "a bezel wider than this 64x36 screen";
    const auto first = huge.output.find(warning);
    EXPECT_NE(first, std::string::npos) << huge.output;
    EXPECT_EQ(huge.output.find(warning, first + 1), std::string::npos) << "once, not every frame:\n"
                                                                       << huge.output;
    const CommandResult tall = run_puddle(wall + "--set wall.bezel_y=40");
    EXPECT_NE(tall.output.find(warning), std::string::npos) << tall.output;
    const CommandResult usual = run_puddle(wall + "--set wall.bezel_x=12 --set wall.bezel_y=12");
    EXPECT_EQ(usual.exit_code, 0) << usual.output;
    EXPECT_EQ(usual.output.find("bezel wider"), std::string::npos) << usual.output;
}

TEST(WallEndToEnd, ScreenshotAtRefusesWithoutTheRealtimeClockOrATimeInThePast) {
    const CommandResult frame_clock = run_puddle("-b headless --size 32x18 --screenshot-at 9999999999");
    EXPECT_EQ(frame_clock.exit_code, 2);
    EXPECT_NE(frame_clock.output.find("--screenshot-at needs wall.clock = \"realtime\""), std::string::npos)
        << frame_clock.output;
    const CommandResult past =
        run_puddle("-b headless --size 32x18 --set wall.clock=realtime --screenshot-at 1000");
    EXPECT_EQ(past.exit_code, 2);
    EXPECT_NE(past.output.find("--screenshot-at 1000.000: that time is"), std::string::npos) << past.output;
    EXPECT_NE(past.output.find("s in the past"), std::string::npos) << past.output;
    // Past the int64 nanoseconds of 2262, and centuries ahead: refused, not waited for or wrapped around.
    for (const char* at : {"9300000000", "9000000000", "nan"}) {
        const CommandResult far = run_puddle(
            std::string("-b headless --size 32x18 --set wall.clock=realtime --screenshot-at ") + at);
        EXPECT_EQ(far.exit_code, 2) << at;
        EXPECT_NE(far.output.find("give a time from now to a day ahead"), std::string::npos) << far.output;
    }
}

}  // namespace
}  // namespace puddle::test
