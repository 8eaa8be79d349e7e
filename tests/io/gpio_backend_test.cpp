// Choosing the GPIO backend (io/gpio_backend.hpp): only "gpiod" and "mock:PATH" are backends, "mock:"
// makes the mock, and the libgpiod backend fails clearly where there is no chip.
#include "io/gpio_backend.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace puddle::io {
namespace {

TEST(GpioBackendSpec, OnlyGpiodAndMockPathAreBackends) {
    EXPECT_TRUE(check_gpio_spec("").ok());
    EXPECT_TRUE(check_gpio_spec("gpiod").ok());
    EXPECT_TRUE(check_gpio_spec("mock:/tmp/knobs.txt").ok());
    for (const char* bad : {"bogus", "gpiod2", "Mock:/x"}) {
        auto r = check_gpio_spec(bad);
        ASSERT_FALSE(r.ok()) << bad;
        EXPECT_EQ(r.error().code, ExitCode::Config);
        EXPECT_EQ(r.error().message,
                  fmt::format("--gpio {}: expected \"gpiod\" or \"mock:PATH\" (a script or FIFO "
                              "of line changes)",
                              bad));
    }
}

// The libgpiod backend this build has, on this machine: with no GPIO chip it must fail clearly.
TEST(GpiodBackend, AMissingChipIsAClearErrorNotACrash) {
    if (std::filesystem::exists("/dev/gpiochip0")) GTEST_SKIP() << "this machine has a GPIO chip";
    auto gpio = make_gpiod_backend();
    auto line = gpio->request({"gpiochip0", "17", true, params::LineBias::PullUp});
    ASSERT_FALSE(line);
    EXPECT_NE(line.error().message.find("gpio: gpiochip0 line 17"), std::string::npos)
        << line.error().message;
    EXPECT_NE(line.error().message.find("gpiodetect"), std::string::npos) << line.error().message;
}

TEST(GpioBackendSpec, MockMakesTheMockBackendAndGpiodTheLibgpiodOne) {
    auto mock = make_gpio_backend("mock:");
    ASSERT_TRUE(mock.ok()) << mock.error().message;
    EXPECT_EQ((*mock)->name(), "mock");
    const auto chips = (*mock)->chips();
    ASSERT_EQ(chips.size(), 1u);
    EXPECT_EQ(chips[0].name, "gpiochip0");
    EXPECT_EQ(chips[0].label, "mock-gpio");
    auto gpiod = make_gpio_backend("gpiod");
    ASSERT_TRUE(gpiod.ok()) << gpiod.error().message;
    EXPECT_NE((*gpiod)->name(), "mock");
    auto by_default = make_gpio_backend("");
    ASSERT_TRUE(by_default.ok()) << by_default.error().message;
    EXPECT_EQ((*gpiod)->name(), (*by_default)->name()) << "gpiod is the default";
    auto bad = make_gpio_backend("mock");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ExitCode::Config);
}

}  // namespace
}  // namespace puddle::io
