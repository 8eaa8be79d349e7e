// Knobs on the mock GPIO backend: the same Knob code that runs on libgpiod.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "io/gpio_mock.hpp"
#include "io/knob.hpp"
#include "support/test_support.hpp"

namespace puddle::io {
namespace {

using params::KnobKind;
using params::KnobSpec;
using params::ParamId;

KnobSpec encoder(double step = 0.05, double acceleration = 0) {
    KnobSpec k;
    k.kind = KnobKind::Encoder;
    k.line = "17";
    k.line_b = "18";
    k.param = ParamId::rain_intensity;
    k.step = step;
    k.acceleration = acceleration;
    return k;
}

KnobSpec button(params::ButtonAction action) {
    KnobSpec k;
    k.kind = KnobKind::Button;
    k.line = "27";
    k.action = action;
    k.active_low = true;
    k.bias = params::LineBias::PullUp;
    return k;
}

// One clockwise detent (A leads) from rest 11, edges 1 ms apart starting at t.
void turn_clockwise(MockGpio& gpio, double t) {
    gpio.set_level("gpiochip0", 17, false, t);
    gpio.set_level("gpiochip0", 18, false, t + 0.001);
    gpio.set_level("gpiochip0", 17, true, t + 0.002);
    gpio.set_level("gpiochip0", 18, true, t + 0.003);
}
void turn_counter_clockwise(MockGpio& gpio, double t) {
    gpio.set_level("gpiochip0", 18, false, t);
    gpio.set_level("gpiochip0", 17, false, t + 0.001);
    gpio.set_level("gpiochip0", 18, true, t + 0.002);
    gpio.set_level("gpiochip0", 17, true, t + 0.003);
}

struct Rig {
    MockGpio gpio;
    std::vector<KnobAction> actions;
    Rig() {
        actions.reserve(64);
        gpio.set_level("gpiochip0", 17, true, 0);
        gpio.set_level("gpiochip0", 18, true, 0);
    }
};

TEST(Knob, EncoderTurnsGiveSignedSteps) {
    Rig rig;
    Knob knob(encoder(0.05));
    knob.update(rig.gpio, 1.0, rig.actions);
    ASSERT_TRUE(knob.open());
    turn_clockwise(rig.gpio, 2.0);
    turn_clockwise(rig.gpio, 3.0);
    turn_counter_clockwise(rig.gpio, 4.0);
    knob.update(rig.gpio, 4.1, rig.actions);
    ASSERT_EQ(rig.actions.size(), 3u);
    EXPECT_DOUBLE_EQ(rig.actions[0].amount, 0.05);
    EXPECT_DOUBLE_EQ(rig.actions[1].amount, 0.05);
    EXPECT_DOUBLE_EQ(rig.actions[2].amount, -0.05);
}

TEST(Knob, AccelerationGrowsTheStepForFastTurnsOnly) {
    Rig rig;
    Knob knob(encoder(0.05, 1.0));
    knob.update(rig.gpio, 1.0, rig.actions);
    turn_clockwise(rig.gpio, 2.0);  // slow: a second after nothing
    turn_clockwise(rig.gpio, 3.0);  // 1 detent/s: no gain
    for (int i = 0; i < 4; ++i) turn_clockwise(rig.gpio, 3.05 + 0.05 * i);  // 20 detents/s
    knob.update(rig.gpio, 4.0, rig.actions);
    ASSERT_EQ(rig.actions.size(), 6u);
    EXPECT_DOUBLE_EQ(rig.actions[1].amount, 0.05);
    EXPECT_NEAR(rig.actions[5].amount, 0.05 * (1 + (20 - 2) / 6.0), 1e-6);
}

TEST(Knob, ButtonPressIsDebouncedAndReportedOnce) {
    Rig rig;
    Knob knob(button(params::ButtonAction::NextPreset));
    knob.update(rig.gpio, 1.0, rig.actions);
    ASSERT_TRUE(knob.open());
    EXPECT_TRUE(rig.actions.empty()) << "pull-up, active low: released at rest";
    // Press with bounce, then hold.
    rig.gpio.set_level("gpiochip0", 27, false, 2.000);
    rig.gpio.set_level("gpiochip0", 27, true, 2.002);
    rig.gpio.set_level("gpiochip0", 27, false, 2.004);
    knob.update(rig.gpio, 2.010, rig.actions);
    EXPECT_TRUE(rig.actions.empty()) << "not yet held for 20 ms";
    knob.update(rig.gpio, 2.030, rig.actions);
    ASSERT_EQ(rig.actions.size(), 1u);
    EXPECT_EQ(rig.actions[0].kind, KnobAction::Kind::Press);
    // Release with bounce: no second press.
    rig.gpio.set_level("gpiochip0", 27, true, 3.000);
    rig.gpio.set_level("gpiochip0", 27, false, 3.001);
    rig.gpio.set_level("gpiochip0", 27, true, 3.002);
    knob.update(rig.gpio, 3.1, rig.actions);
    EXPECT_EQ(rig.actions.size(), 1u);
}

TEST(Knob, SwitchReportsItsPositionAtOnceAndOnChange) {
    Rig rig;
    KnobSpec k;
    k.kind = KnobKind::Switch;
    k.line = "22";
    k.param = ParamId::ground_checkerboard;
    rig.gpio.set_level("gpiochip0", 22, true, 0);
    Knob knob(k);
    knob.update(rig.gpio, 1.0, rig.actions);
    ASSERT_EQ(rig.actions.size(), 1u);
    EXPECT_TRUE(rig.actions[0].level);
    rig.gpio.set_level("gpiochip0", 22, false, 2.0);
    knob.update(rig.gpio, 2.5, rig.actions);
    ASSERT_EQ(rig.actions.size(), 2u);
    EXPECT_EQ(rig.actions[1].kind, KnobAction::Kind::Level);
    EXPECT_FALSE(rig.actions[1].level);
}

TEST(Knob, MissingChipWarnsAndStartsWorkingWhenItAppears) {
    Rig rig;
    KnobSpec k = encoder();
    k.chip = "gpiochip1";
    Knob knob(k);
    knob.update(rig.gpio, 1.0, rig.actions);
    EXPECT_FALSE(knob.open());
    rig.gpio.add_chip("gpiochip1", "usb-expander");
    rig.gpio.set_level("gpiochip1", 17, true, 1.5);
    rig.gpio.set_level("gpiochip1", 18, true, 1.5);
    knob.update(rig.gpio, 2.0, rig.actions);
    EXPECT_FALSE(knob.open()) << "retries only every few seconds";
    knob.update(rig.gpio, 1.0 + Knob::retry_seconds, rig.actions);
    EXPECT_TRUE(knob.open());
}

TEST(Knob, UnpluggedChipClosesTheKnobAndReplugReopensIt) {
    Rig rig;
    Knob knob(encoder());
    knob.update(rig.gpio, 1.0, rig.actions);
    ASSERT_TRUE(knob.open());
    rig.gpio.remove_chip("gpiochip0");
    knob.update(rig.gpio, 2.0, rig.actions);
    EXPECT_FALSE(knob.open());
    rig.gpio.add_chip("gpiochip0");
    knob.update(rig.gpio, 2.0 + Knob::retry_seconds, rig.actions);
    EXPECT_TRUE(knob.open());
}

TEST(GpioMock, FaultMessagesNameChipLineAndFix) {
    MockGpio gpio;
    LineRequest r{"gpiochip0", "17"};
    gpio.set_error("gpiochip0", 17, EACCES);
    auto denied = gpio.request(r);
    ASSERT_FALSE(denied);
    EXPECT_NE(denied.error().message.find("gpiochip0 line 17"), std::string::npos) << denied.error().message;
    EXPECT_NE(denied.error().message.find("group gpio"), std::string::npos) << denied.error().message;
    EXPECT_NE(denied.error().message.find("deploy/99-puddle-gpio.rules"), std::string::npos);
    gpio.set_error("gpiochip0", 17, 0);
    auto first = gpio.request(r);
    ASSERT_TRUE(first);
    auto busy = gpio.request(r);
    ASSERT_FALSE(busy);
    EXPECT_NE(busy.error().message.find("busy"), std::string::npos) << busy.error().message;
    auto missing = gpio.request({"gpiochip7", "3"});
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("gpiodetect"), std::string::npos) << missing.error().message;
}

TEST(GpioMock, FindsChipsByNamePathNumberAndLabelAndLinesByName) {
    MockGpio gpio;
    EXPECT_TRUE(gpio.request({"/dev/gpiochip0", "1"}));
    EXPECT_TRUE(gpio.request({"0", "2"}));
    EXPECT_TRUE(gpio.request({"mock-gpio", "3"}));
    EXPECT_TRUE(gpio.request({"gpiochip0", "GPIO4"}));
    EXPECT_FALSE(gpio.request({"gpiochip0", "GPIO99"}));
}

TEST(GpioMock, ScriptDrivesLinesAndWaits) {
    test::TempDir dir;
    const std::string script = dir.write("gpio.txt", "gpiochip0 5 1\nwait 1.0\ngpiochip0 5 0\n");
    MockGpio gpio(script);
    auto line = gpio.request({"gpiochip0", "5"});
    ASSERT_TRUE(line);
    auto level = [&] { return (*line)->level().value(); };
    gpio.poll(10.0);
    EXPECT_TRUE(level());
    gpio.poll(10.5);
    EXPECT_TRUE(level()) << "still waiting";
    gpio.poll(11.1);
    EXPECT_FALSE(level());
    std::ofstream(script, std::ios::app) << "gpiochip0 5 1\n";  // followed like tail -f
    gpio.poll(12.0);
    EXPECT_TRUE(level());
    LineEvent events[8];
    auto n = (*line)->read_events(events);
    ASSERT_TRUE(n);
    EXPECT_EQ(*n, 3u);
}

// Issue 15: a mock script is a file Puddle reads: an offset too large for an int (std::stoi threw and
// ended the process) is no command, and a line too long to be one is skipped, not kept in memory.
TEST(GpioMock, AHugeOffsetOrAnEndlessLineIsSkippedAndTheScriptGoesOn) {
    test::TempDir dir;
    const std::string script = dir.write("gpio.txt", "gpiochip0 99999999999 1\nbusy gpiochip0 99999999999\n" +
                                                         std::string(200000, 'x') + "\ngpiochip0 5 1\n");
    MockGpio gpio(script);
    auto line = gpio.request({"gpiochip0", "5"});
    ASSERT_TRUE(line);
    for (int i = 0; i < 8; ++i) gpio.poll(10.0 + i);  // 64 KiB a poll: four polls reach the last line
    EXPECT_TRUE((*line)->level().value()) << "the command after the long line ran";
    EXPECT_FALSE(gpio.command("gpiochip0 99999999999 1", 20.0));
    EXPECT_FALSE(gpio.command("deny gpiochip0 99999999999", 20.0));
}

// A wait that is no sensible time (negative, NaN, a billion seconds) is skipped with a warning: "wait 1e12"
// had stopped the rest of the script for good.
TEST(GpioMock, AWaitOutsideZeroToADayIsSkippedAndTheScriptGoesOn) {
    test::TempDir dir;
    const std::string script = dir.write("gpio.txt", "wait 1e12\nwait nan\nwait -1\ngpiochip0 5 1\n");
    MockGpio gpio(script);
    auto line = gpio.request({"gpiochip0", "5"});
    ASSERT_TRUE(line);
    gpio.poll(10.0);
    gpio.poll(10.1);
    EXPECT_TRUE((*line)->level().value()) << "the command after the bad waits ran";
}

TEST(GpioBackendSpec, OnlyGpiodAndMockPathAreBackends) {
    EXPECT_TRUE(check_gpio_spec("").ok());
    EXPECT_TRUE(check_gpio_spec("gpiod").ok());
    EXPECT_TRUE(check_gpio_spec("mock:/tmp/knobs.txt").ok());
    for (const char* bad : {"bogus", "gpiod2", "Mock:/x"}) {
        auto r = check_gpio_spec(bad);
        ASSERT_FALSE(r.ok()) << bad;
        EXPECT_EQ(r.error().code, ExitCode::Config);
        EXPECT_EQ(r.error().message, fmt::format("--gpio {}: expected \"gpiod\" or \"mock:PATH\" (a script or FIFO "
                                                 "of line changes)",
                                                 bad));
    }
}

}  // namespace
}  // namespace puddle::io

namespace puddle::io {
namespace {

// The libgpiod backend this build has, on this machine: with no GPIO chip it must fail clearly.
TEST(GpiodBackend, AMissingChipIsAClearErrorNotACrash) {
    if (std::filesystem::exists("/dev/gpiochip0")) GTEST_SKIP() << "this machine has a GPIO chip";
    auto gpio = make_gpiod_backend();
    auto line = gpio->request({"gpiochip0", "17", true, params::LineBias::PullUp});
    ASSERT_FALSE(line);
    EXPECT_NE(line.error().message.find("gpio: gpiochip0 line 17"), std::string::npos) << line.error().message;
    EXPECT_NE(line.error().message.find("gpiodetect"), std::string::npos) << line.error().message;
}

}  // namespace
}  // namespace puddle::io
