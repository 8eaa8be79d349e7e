// `puddle --check` on this machine (no DRM, no GPIO, no camera): each absence said clearly, exit 0;
// knobs checked against the GPIO backend; an invalid config is the one thing that fails it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <sys/wait.h>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

struct Outcome {
    int exit_code = -1;
    std::string out;
};

Outcome check(const std::string& args) {
    FILE* p = popen((std::string(PUDDLE_BINARY) + " --check " + args + " 2>&1").c_str(), "r");
    Outcome o;
    char buf[1024];
    while (std::fgets(buf, sizeof buf, p)) o.out += buf;
    const int status = pclose(p);
    o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return o;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(Check, ReportsEachAbsenceOnThisMachineAndExitsZero) {
    const Outcome o = check("");
    EXPECT_EQ(o.exit_code, 0) << o.out;
    for (const char* section : {"[config]", "[display: DRM/KMS", "[GPU: EGL and OpenGL ES]", "[GPIO knobs", "[cameras (V4L2)]"})
        EXPECT_TRUE(has(o.out, section)) << section << "\n" << o.out;
    EXPECT_TRUE(has(o.out, "OK    ")) << "the GPU line:\n" << o.out;
    EXPECT_TRUE(has(o.out, "OpenGL ES 3")) << o.out;
    if (!has(o.out, "/dev/dri/card")) {
        EXPECT_TRUE(has(o.out, "--    no /dev/dri/card*")) << o.out;
    }
    if (!has(o.out, "gpiochip0 \"")) {
        EXPECT_TRUE(has(o.out, "--    no GPIO chips")) << o.out;
    }
    if (!has(o.out, "OK    /dev/video")) {
        EXPECT_TRUE(has(o.out, "--    no /dev/video*")) << o.out;
    }
    EXPECT_FALSE(has(o.out, "info:")) << "the report is the output, not the log:\n" << o.out;
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
    const Outcome o = check("--gpio mock: --config " + cfg);
    EXPECT_EQ(o.exit_code, 0) << "hardware problems are reported, not fatal:\n" << o.out;
    EXPECT_TRUE(has(o.out, "OK    gpiochip0 \"mock-gpio\", 64 lines")) << o.out;
    EXPECT_TRUE(has(o.out, "OK    knob 1: encoder rain.intensity on gpiochip0 lines 17/18")) << o.out;
    EXPECT_TRUE(has(o.out, "FIX   knob 2 (button save on gpiochip4 line 3): gpio: gpiochip4 line 3: no such chip")) << o.out;
    EXPECT_TRUE(has(o.out, "1 thing(s) to fix")) << o.out;
}

TEST(Check, AnInvalidConfigIsExitCodeTwoWithFileLine) {
    TempDir dir;
    const std::string cfg = dir.write("bad.toml", "[rain]\ndrop_count = 999\n");
    const Outcome o = check("--config " + cfg);
    EXPECT_EQ(o.exit_code, 2) << o.out;
    EXPECT_TRUE(has(o.out, "FIX   config: " + cfg + ":2: rain.drop_count = 999")) << o.out;
}

}  // namespace
}  // namespace puddle::test
