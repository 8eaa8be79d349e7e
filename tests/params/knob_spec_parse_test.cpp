// Reading a [[knob]] table (params/knob_spec_parse.hpp), through the config loader as Puddle reads it:
// the three kinds with their defaults, each mistake named with file, line and what is expected, numbers
// checked as written.
#include "params/knob_spec_parse.hpp"

#include <gtest/gtest.h>

#include <string>

#include "params/config_loader.hpp"
#include "support/parsed_config.hpp"

namespace puddle::params {
namespace {

Config config(const char* text) {
    return test::parsed_config(text);
}

TEST(ConfigKnobs, ParsesTheThreeKindsWithDefaults) {
    const Config c = config(R"(
[[knob]]
kind = "encoder"
chip = "pinctrl-bcm2711"
a = 17
b = "GPIO18"
param = "rain.intensity"
acceleration = 1.5
bias = "pull-up"
active_low = true

[[knob]]
kind = "button"
line = 27
action = "toggle"
param = "ground.checkerboard"

[[knob]]
kind = "switch"
line = 22
param = "ground.checkerboard"
debounce_ms = 50
)");
    ASSERT_EQ(c.knobs.size(), 3u);
    EXPECT_EQ(c.knobs[0].chip, "pinctrl-bcm2711");
    EXPECT_EQ(c.knobs[0].line, "17");
    EXPECT_EQ(c.knobs[0].line_b, "GPIO18");
    EXPECT_NEAR(c.knobs[0].step, 4.0 / 50, 1e-9) << "default step: 1/50 of the range";
    EXPECT_EQ(c.knobs[0].bias, LineBias::PullUp);
    EXPECT_TRUE(c.knobs[0].active_low);
    EXPECT_EQ(c.knobs[1].action, ButtonAction::Toggle);
    EXPECT_EQ(c.knobs[1].chip, "gpiochip0");
    EXPECT_EQ(c.knobs[2].debounce_ms, 50);
}

TEST(ConfigKnobs, MistakesNameFileLineAndWhatIsExpected) {
    struct Case {
        const char* text;
        const char* expect;
    };
    const Case cases[] = {
        {"[[knob]]\nkind = \"dial\"\n", "kind must be"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nparam = \"rain.intensity\"\n", "'b' is missing"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\nparam = \"rain.intensty\"\n",
         "did you mean 'rain.intensity'"},
        {"[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\nparam = \"ground.checkerboard\"\n",
         "a number parameter"},
        {"[[knob]]\nkind = \"switch\"\nline = 3\nparam = \"rain.intensity\"\n", "true/false parameter"},
        {"[[knob]]\nkind = \"button\"\nline = 3\n", "needs an action"},
        {"[[knob]]\nkind = \"button\"\nline = 3\naction = \"save\"\nspin = 2\n", "unknown key 'spin'"},
        {"[[knob]]\nkind = \"button\"\nline = -3\naction = \"save\"\n", "line must be"},
        {"[[knob]]\nkind = \"encoder\"\na = 17\nb = 17\nparam = \"rain.intensity\"\n",
         "k.toml:4: knob 1: a and b are both line 17: an encoder needs two lines"},
    };
    for (const Case& c : cases) {
        auto r = parse_config(c.text, "k.toml");
        ASSERT_FALSE(r) << c.text;
        EXPECT_NE(r.error().message.find("k.toml:"), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(c.expect), std::string::npos) << r.error().message;
    }
}

// Issue 15, fault 3: a knob's numbers are checked as written, before anything narrows them.
TEST(ConfigKnobs, NumbersAreCheckedBeforeTheyAreStored) {
    const std::string encoder = "[[knob]]\nkind = \"encoder\"\na = 1\nb = 2\n";
    const std::string button = "[[knob]]\nkind = \"button\"\naction = \"save\"\n";
    struct Case {
        std::string text;
        const char* message;
    };
    const Case cases[] = {
        {button + "line = 3\ndebounce_ms = 20.5\n",  // was 20
         "config: k.toml:5: knob 1: debounce_ms = 20.5 is not allowed: a whole number from 0 to 1000"},
        {button + "line = 3\ndebounce_ms = 4294967316\n",
         "config: k.toml:5: knob 1: debounce_ms = 4294967316 is not allowed: a whole number from 0 to 1000"},
        {encoder + "param = \"rain.drop_count\"\nstep = 0.5\n",  // was 1
         "config: k.toml:6: knob 1: step = 0.5 is not a whole number, and rain.drop_count is an integer"},
        {encoder + "param = \"rain.intensity\"\nstep = 40\n",
         "config: k.toml:6: knob 1: step = 40 is larger than the whole range of rain.intensity (0 to 4)"},
        {button + "line = \"99999999999\"\n",  // std::stoi threw when the line was requested
         "config: k.toml:4: knob 1: line must be a line offset (0 to 4095) or a line name (at most 64 "
         "bytes)"},
    };
    for (const Case& c : cases) {
        auto r = parse_config(c.text, "k.toml");
        ASSERT_FALSE(r) << c.text;
        EXPECT_EQ(r.error().message, c.message);
    }
    auto named = parse_config(button + "line = \"17\"\n", "k.toml");
    ASSERT_TRUE(named) << named.error().message;
    EXPECT_EQ(named->knobs[0].line, "17");
}

}  // namespace
}  // namespace puddle::params
