#include "io/gpio_mock.hpp"

#include <gtest/gtest.h>

#include <array>

namespace puddle::io {
namespace {

// Seen while writing tests/fuzz/gpio_mock_fuzz.cpp: an offset with more digits than an int holds reached std::stoi,
// whose std::out_of_range escaped the frame loop's poll and ended the program.
TEST(MockGpio, AnOffsetPastAnyChipIsNotACommand) {
    MockGpio gpio;
    EXPECT_FALSE(gpio.command("gpiochip0 99999999999 1", 0));
    EXPECT_FALSE(gpio.command("busy gpiochip0 99999999999", 0));
    EXPECT_FALSE(gpio.command("deny gpiochip0 4294967313", 0));
    // An offset in range still works, and the line was not made busy by the refused commands.
    EXPECT_TRUE(gpio.command("busy gpiochip0 17", 0));
    auto busy = gpio.request({.chip = "gpiochip0", .line = "17"});
    ASSERT_FALSE(busy.ok());
    auto free_line = gpio.request({.chip = "gpiochip0", .line = "18"});
    EXPECT_TRUE(free_line.ok());
}

TEST(MockGpio, RequestingAnOffsetPastAnyChipIsNoSuchLine) {
    MockGpio gpio;
    for (const char* line : {"99999999999", "GPIO99999999999", "2147483648", "64"}) {
        auto requested = gpio.request({.chip = "gpiochip0", .line = line});
        ASSERT_FALSE(requested.ok()) << line;
        EXPECT_NE(requested.error().message.find(line), std::string::npos) << requested.error().message;
    }
}

TEST(GpioLineOffset, DigitsWithinRangeOnly) {
    EXPECT_EQ(line_offset("0"), 0);
    EXPECT_EQ(line_offset("17"), 17);
    EXPECT_EQ(line_offset("65535"), 65535);
    EXPECT_EQ(line_offset("65536"), std::nullopt);
    EXPECT_EQ(line_offset("99999999999999999999"), std::nullopt);
    EXPECT_EQ(line_offset("GPIO17"), std::nullopt);
    EXPECT_EQ(line_offset("-1"), std::nullopt);
    EXPECT_EQ(line_offset(""), std::nullopt);
}

}  // namespace
}  // namespace puddle::io
