// `puddle --check`: the report line by line. What the machine has (DRM cards, cameras, the GPU's features)
// is found here independently (the test lists /dev and probes a Device of its own) and each section must
// say exactly that; GPIO runs on the mock backend so its lines are fixed. Knobs are checked against the
// GPIO backend; an invalid config is the one thing that fails it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/version.hpp"
#include "gpu/device.hpp"
#include "platform/display.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

CommandResult check(const std::string& args) {
    return run_puddle("--check " + args);
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The report's lines under each "[section]" header (log lines on stderr, which do not start with two
// spaces, are left out); the lines before the first header under "".
std::map<std::string, std::vector<std::string>> sections(const std::string& output) {
    std::map<std::string, std::vector<std::string>> out;
    std::string current;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("["))
            current = line;
        else if (line.starts_with("  ") || (current.empty() && line.starts_with("puddle ")))
            out[current].push_back(line);
    }
    return out;
}

// /dev entries whose names start with `prefix`, sorted.
std::vector<std::string> dev_entries(const std::filesystem::path& dir, const std::string& prefix) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().filename().string().starts_with(prefix)) found.push_back(e.path().string());
    std::sort(found.begin(), found.end());
    return found;
}

// What the GPU section must say: the capabilities of a Device made here, on the same driver.
std::vector<std::string> expected_gpu_lines() {
    auto display =
        platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {16, 16}});
    EXPECT_TRUE(display.ok()) << (display.ok() ? "" : display.error().message);
    if (!display) return {};
    const gpu::Device device;
    const gpu::Capabilities& c = device.caps();
    std::vector<std::string> lines{"  OK    " + c.vendor + " / " + c.renderer + " / " + c.version};
    auto feature = [&](bool have, const std::string& what, const std::string& without) {
        lines.push_back(have ? "  OK    " + what : "  --    " + what + ": missing; " + without);
    };
    feature(c.float_render_targets, "float render targets (wave field in RG32F)",
            "the wave field runs in fixed point (RG32I), the same picture");
    feature(c.half_float_render_targets, "half-float render targets (HDR sky, surface)",
            "HDR skies are stored as RGBM, the surface as RGBA8");
    feature(c.float_linear_filtering, "filtering of 32-bit float textures",
            "not needed: Puddle never filters them");
    feature(c.timer_queries, "timer queries", "--stats and puddle-bench show CPU times only");
    feature(c.external_images, "external images (OES_EGL_image_external_essl3)", "camera frames are copied");
    feature(platform::current_display_has_extension("EGL_EXT_image_dma_buf_import"),
            "dmabuf import (EGL_EXT_image_dma_buf_import)", "camera frames are copied (glTexSubImage2D)");
    feature(c.anisotropic_filtering, "anisotropic filtering", "the ground is filtered trilinearly");
    return lines;
}

// Each of `paths` has a line of its own in `lines`: OK, FIX or absent ("--"), naming it first.
void expect_each_named(const std::vector<std::string>& lines, const std::vector<std::string>& paths) {
    for (const std::string& path : paths)
        EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
            return l.starts_with("  OK    " + path) || l.starts_with("  FIX   " + path) ||
                   l.starts_with("  --    " + path);
        })) << path;
}

TEST(Check, ReportsWhatThisMachineHasLineByLine) {
    TempDir dir;
    const std::string cfg = dir.write("ok.toml", "[rain]\ndrop_count = 40\n[water]\nturbidity = 0.2\n");
    const CommandResult o = check("--gpio mock: --config " + cfg);
    EXPECT_EQ(o.exit_code, 0) << o.output;
    auto s = sections(o.output);
    EXPECT_EQ(s[""], std::vector<std::string>{"puddle " + std::string(app::version()) + " --check"})
        << o.output;
    EXPECT_EQ(s["[config]"], std::vector<std::string>{"  OK    " + cfg + ": valid (2 values, 0 knobs)"});

    const std::vector<std::string> cards = dev_entries("/dev/dri", "card");
    const auto& drm = s["[display: DRM/KMS (--backend kms)]"];
    if (cards.empty())
        EXPECT_EQ(drm,
                  std::vector<std::string>{"  --    no /dev/dri/card*: no KMS screen here (the window and "
                                           "headless backends still work)"});
    else
        expect_each_named(drm, cards);

    EXPECT_EQ(s["[GPU: EGL and OpenGL ES]"], expected_gpu_lines());
    EXPECT_EQ(s["[GPIO knobs (libgpiod)]"],
              (std::vector<std::string>{"  OK    gpiochip0 \"mock-gpio\", 64 lines",
                                        "  --    no [[knob]] in the config"}));

    const std::vector<std::string> videos = dev_entries("/dev", "video");
    const auto& cameras = s["[cameras (V4L2)]"];
    if (videos.empty())
        EXPECT_EQ(cameras,
                  std::vector<std::string>{"  --    no /dev/video*: environment.source = \"camera\" would "
                                           "show the cubemap"});
    else
        expect_each_named(cameras, videos);

    // The last line counts the FIX lines above it.
    long fix_lines = 0;
    for (const auto& [name, lines] : s)
        fix_lines += std::count_if(lines.begin(), lines.end(),
                                   [](const std::string& l) { return l.starts_with("  FIX   "); });
    EXPECT_TRUE(has(o.output, fix_lines == 0
                                  ? "\nEverything Puddle needs here is in order.\n"
                                  : "\n" + std::to_string(fix_lines) + " thing(s) to fix (FIX above).\n"))
        << o.output;
    EXPECT_FALSE(has(o.output, "info:")) << "the report is the output, not the log:\n" << o.output;
}

// Without --config the default path is used when it exists, and its absence is said (not an error).
TEST(Check, WithoutAConfigNamesTheDefaultPathOrItsAbsence) {
    const CommandResult o = check("--gpio mock:");
    const auto config = sections(o.output)["[config]"];
    ASSERT_EQ(config.size(), 1u) << o.output;
    if (std::filesystem::exists("/etc/puddle/puddle.toml")) {
        EXPECT_TRUE(config[0].starts_with("  OK    /etc/puddle/puddle.toml: valid (") ||
                    config[0].starts_with("  FIX   config: /etc/puddle/puddle.toml:"))
            << config[0];
    } else {
        EXPECT_EQ(o.exit_code, 0) << o.output;
        EXPECT_EQ(
            config[0],
            "  --    no config file (/etc/puddle/puddle.toml does not exist): built-in defaults are used");
    }
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
    const std::string state = (dir / "state.toml").string();
    const CommandResult o = check("--gpio mock: --config " + cfg + " --state " + state);
    EXPECT_EQ(o.exit_code, 0) << "hardware problems are reported, not fatal:\n" << o.output;
    EXPECT_EQ(
        sections(o.output)["[saved knob state]"],
        (std::vector<std::string>{"  --    " + state + ": none yet (knob changes will be saved there)"}))
        << o.output;
    EXPECT_EQ(
        sections(o.output)["[GPIO knobs (libgpiod)]"],
        (std::vector<std::string>{
            "  OK    gpiochip0 \"mock-gpio\", 64 lines",
            "  OK    knob 1: encoder rain.intensity on gpiochip0 lines 17/18",
            "  FIX   knob 2 (button save on gpiochip4 line 3): gpio: gpiochip4 line 3: no such chip or line "
            "(list them with gpiodetect and gpioinfo)"}))
        << o.output;
    EXPECT_TRUE(has(o.output, "\n1 thing(s) to fix (FIX above).\n")) << o.output;
}

// A start drops saved values that are no longer valid (a parameter renamed, a range narrowed); --check
// says which before that happens, and changes nothing on disk.
TEST(Check, NamesTheSavedValuesAStartWouldDrop) {
    TempDir dir;
    const std::string cfg =
        dir.write("k.toml", "[[knob]]\nkind = \"encoder\"\na = 17\nb = 18\nparam = \"rain.intensity\"\n");
    const std::string text = "[rain]\nintensity = 0.5\nwind = 1\n[water]\nturbidity = 9\n";
    const std::string state = dir.write("state.toml", text);
    const CommandResult o = check("--gpio mock: --config " + cfg + " --state " + state);
    EXPECT_EQ(o.exit_code, 0) << o.output;
    EXPECT_EQ(
        sections(o.output)["[saved knob state]"],
        (std::vector<std::string>{"  FIX   state: " + state +
                                      ":3: unknown key 'rain.wind' (did you mean 'rain.seed'?); dropped that "
                                      "value, kept the others",
                                  "  FIX   state: " + state +
                                      ":5: water.turbidity = 9 is out of range: allowed a number from 0 to 2 "
                                      "1/unit; dropped that value, kept the others",
                                  "        a start sets this file aside as state.toml.bad-* and keeps its "
                                  "valid values; where it cannot, "
                                  "it leaves the file alone and saves no knob change",
                                  "  OK    " + state + ": 1 saved value(s)"}))
        << o.output;
    EXPECT_EQ(read_file(state), text) << "--check changes nothing";
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2) << "no copy was made";
}

TEST(Check, AnInvalidConfigIsExitCodeTwoWithFileLine) {
    TempDir dir;
    const std::string cfg = dir.write("bad.toml", "[rain]\ndrop_count = 999\n");
    const CommandResult o = check("--gpio mock: --config " + cfg);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    const auto config = sections(o.output)["[config]"];
    ASSERT_EQ(config.size(), 1u) << o.output;
    EXPECT_TRUE(config[0].starts_with("  FIX   config: " + cfg + ":2: rain.drop_count = 999")) << config[0];
    EXPECT_TRUE(has(o.output, "\n1 thing(s) to fix (FIX above).\n")) << o.output;
}

}  // namespace
}  // namespace puddle::test
