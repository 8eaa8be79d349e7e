// `puddle --check` on this machine (no DRM, no GPIO, no camera): each absence said clearly, exit 0;
// knobs checked against the GPIO backend; an invalid config is the one thing that fails it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <sys/wait.h>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

CommandResult check(const std::string& args) { return run_puddle("--check " + args); }

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Check, ReportsEachAbsenceOnThisMachineAndExitsZero) {
    const CommandResult o = check("");
    EXPECT_EQ(o.exit_code, 0) << o.output;
    for (const char* section : {"[config]", "[display: DRM/KMS", "[GPU: EGL and OpenGL ES]", "[GPIO knobs", "[cameras (V4L2)]"})
        EXPECT_TRUE(has(o.output, section)) << section << "\n" << o.output;
    EXPECT_TRUE(has(o.output, "OK    ")) << "the GPU line:\n" << o.output;
    EXPECT_TRUE(has(o.output, "OpenGL ES 3")) << o.output;
    if (!has(o.output, "/dev/dri/card")) {
        EXPECT_TRUE(has(o.output, "--    no /dev/dri/card*")) << o.output;
    }
    if (!has(o.output, "gpiochip0 \"")) {
        EXPECT_TRUE(has(o.output, "--    no GPIO chips")) << o.output;
    }
    if (!has(o.output, "OK    /dev/video")) {
        EXPECT_TRUE(has(o.output, "--    no /dev/video*")) << o.output;
    }
    EXPECT_FALSE(has(o.output, "info:")) << "the report is the output, not the log:\n" << o.output;
}

TEST(Check, ChecksEachKnobAgainstTheGpioChips) {
    TempDir dir;
    const std::string cfg = dir.write("k.toml", R"(
[[knob]]
kind = "encoder"
a = 17
b = 18
param = "rain.intensity"

[[knob]]
kind = "button"
chip = "gpiochip4"
line = 3
action = "save"
)");
    const CommandResult o = check("--gpio mock: --config " + cfg);
    EXPECT_EQ(o.exit_code, 0) << "hardware problems are reported, not fatal:\n" << o.output;
    EXPECT_TRUE(has(o.output, "OK    gpiochip0 \"mock-gpio\", 64 lines")) << o.output;
    EXPECT_TRUE(has(o.output, "OK    knob 1: encoder rain.intensity on gpiochip0 lines 17/18")) << o.output;
    EXPECT_TRUE(has(o.output, "FIX   knob 2 (button save on gpiochip4 line 3): gpio: gpiochip4 line 3: no such chip")) << o.output;
    EXPECT_TRUE(has(o.output, "1 thing(s) to fix")) << o.output;
}

TEST(Check, AnInvalidConfigIsExitCodeTwoWithFileLine) {
    TempDir dir;
    const std::string cfg = dir.write("bad.toml", "[rain]\ndrop_count = 999\n");
    const CommandResult o = check("--config " + cfg);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_TRUE(has(o.output, "FIX   config: " + cfg + ":2: rain.drop_count = 999")) << o.output;
}

}  // namespace
}  // namespace puddle::test
