// The mock GPIO backend (io/gpio_mock.hpp): faults named like libgpiod's, chips and lines found by every
// name a config may use, and the script that drives lines from outside the process.
#include "io/gpio_mock.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "support/test_support.hpp"

namespace puddle::io {
namespace {

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

// A source that never runs dry and never ends a line (/dev/zero) held the first frame in read() for ever,
// SIGTERM included: each poll now reads at most 64 KiB. The polls run on a thread of their own, so that
// the old code fails the test instead of hanging it (the thread and the mock are then left behind).
TEST(GpioMock, ASourceThatNeverRunsDryHoldsNoFrame) {
    auto* gpio = new MockGpio("/dev/zero");
    auto done = std::make_shared<std::promise<void>>();
    std::future<void> polled = done->get_future();
    std::thread([gpio, done] {
        for (int i = 0; i < 3; ++i) gpio->poll(1.0 + i);
        done->set_value();
    }).detach();
    ASSERT_EQ(polled.wait_for(std::chrono::seconds(30)), std::future_status::ready)
        << "a poll never returned";
    delete gpio;
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
}  // namespace
}  // namespace puddle::io
