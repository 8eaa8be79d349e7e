// `puddle --check`: the report line by line. The DRM and V4L2 sections read folders the test makes (card
// and video nodes that are plain files or dangling links), so their lines are known from those inputs
// whatever the machine has; the GPU section must name a Device probed here; GPIO runs on the mock backend.
// Knobs are checked against the GPIO backend; an invalid config is the one thing that fails it. The
// config and knob tests run the binary, the folder tests call run_check in this process.
#include "app/check.hpp"

#include <gtest/gtest.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "gpu/device.hpp"
#include "platform/display.hpp"
#include "support/test_support.hpp"
#include "util/version.hpp"

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

// run_check in this process, on folders of the test's own instead of /dev/dri and /dev, with the
// report written to a temporary file and read back.
CommandResult check_here(const std::vector<std::string>& args, const app::CheckSources& folders) {
    std::vector<const char*> argv{"puddle", "--check"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    auto options = app::parse_command_line(static_cast<int>(argv.size()), argv.data());
    EXPECT_TRUE(options.ok()) << (options.ok() ? "" : options.error().message);
    if (!options) return {};
    std::FILE* out = std::tmpfile();
    app::CheckSources sources = folders;
    sources.out = out;
    const auto level = spdlog::get_level();
    CommandResult result{app::run_check(*options, options->config_path, sources), ""};
    spdlog::set_level(level);
    std::rewind(out);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, out)) > 0;) result.output.append(buffer, n);
    std::fclose(out);
    return result;
}

// A folder holding `files` (empty files; "name -> target" makes a symbolic link), for the DRM or V4L2 nodes.
std::string node_folder(TempDir& dir, const std::string& name, const std::vector<std::string>& files) {
    const std::filesystem::path folder = dir / name;
    std::filesystem::create_directories(folder);
    for (const std::string& f : files) {
        if (const auto arrow = f.find(" -> "); arrow != std::string::npos)
            std::filesystem::create_symlink(folder / f.substr(arrow + 4), folder / f.substr(0, arrow));
        else
            std::ofstream(folder / f) << "";
    }
    return folder.string();
}

// What the GPU section must say for a Device made here, on the same driver: its names, then each feature
// in gpu_feature_lines' words (checked on their own in GpuFeatureLines.*), OK when present, "--" when not.
std::vector<std::string> expected_gpu_lines() {
    auto display =
        platform::create_headless_display({.backend = platform::BackendKind::Headless, .size = {16, 16}});
    EXPECT_TRUE(display.ok()) << (display.ok() ? "" : display.error().message);
    if (!display) return {};
    const gpu::Device device;
    const gpu::Capabilities& c = device.caps();
    std::vector<std::string> lines{"  OK    " + c.vendor + " / " + c.renderer + " / " + c.version};
    for (const app::GpuFeatureLine& f :
         app::gpu_feature_lines(c, platform::current_display_has_extension("EGL_EXT_image_dma_buf_import")))
        lines.push_back((f.present ? "  OK    " : "  --    ") + f.text);
    return lines;
}

// Card and video nodes that are not devices: a plain file (a card without KMS outputs, a node that is no
// camera) and a dangling link (a node that vanished); other names are not looked at.
TEST(Check, ReportsTheNodesItIsGivenLineByLine) {
    TempDir dir;
    const std::string cfg = dir.write("ok.toml", "[rain]\ndrop_count = 40\n[water]\nturbidity = 0.2\n");
    const std::string dri = node_folder(dir, "dri", {"card0", "card1 -> gone", "renderD128", "by-path"});
    const std::string dev = node_folder(dir, "dev", {"video0", "video1 -> gone", "v4l-subdev0", "vbi0"});
    const CommandResult o =
        check_here({"--gpio", "mock:", "--config", cfg}, {.dri_folder = dri, .video_folder = dev});
    EXPECT_EQ(o.exit_code, 0) << "hardware problems are reported, not fatal:\n" << o.output;
    auto s = sections(o.output);
    EXPECT_EQ(s[""], std::vector<std::string>{"puddle " + std::string(version()) + " --check"}) << o.output;
    EXPECT_EQ(s["[config]"], std::vector<std::string>{"  OK    " + cfg + ": valid (2 values, 0 knobs)"});
    EXPECT_EQ(s["[display: DRM/KMS (--backend kms)]"],
              (std::vector<std::string>{"  --    " + dri + "/card0: no display outputs (a render-only GPU)",
                                        "  FIX   " + dri + "/card1: cannot open: No such file or directory"}))
        << o.output;
    EXPECT_EQ(s["[GPU: EGL and OpenGL ES]"], expected_gpu_lines());
    EXPECT_EQ(s["[GPIO knobs (libgpiod)]"],
              (std::vector<std::string>{"  OK    gpiochip0 \"mock-gpio\", 64 lines",
                                        "  --    no [[knob]] in the config"}));
    const auto& cameras = s["[cameras (V4L2)]"];
    ASSERT_EQ(cameras.size(), 2u) << o.output;
    EXPECT_EQ(cameras[0], "  --    " + dev + "/video0: offers no capture formats (not a camera?)");
    EXPECT_EQ(cameras[1], "  FIX   " + dev + "/video1: cannot open: No such file or directory");
    EXPECT_TRUE(has(o.output, "\n2 thing(s) to fix (FIX above).\n")) << o.output;
    EXPECT_FALSE(has(o.output, "info:")) << "the report is the output, not the log:\n" << o.output;
}

TEST(Check, FoldersWithoutNodesSayThereIsNoScreenAndNoCamera) {
    TempDir dir;
    const std::string dri = node_folder(dir, "dri", {"renderD128"});
    const std::string dev = node_folder(dir, "dev", {});
    const CommandResult o = check_here({"--gpio", "mock:"}, {.dri_folder = dri, .video_folder = dev});
    auto s = sections(o.output);
    EXPECT_EQ(
        s["[display: DRM/KMS (--backend kms)]"],
        std::vector<std::string>{"  --    no " + dri +
                                 "/card*: no KMS screen here (the window and headless backends still work)"})
        << o.output;
    EXPECT_EQ(s["[cameras (V4L2)]"],
              std::vector<std::string>{"  --    no " + dev +
                                       "/video*: environment.source = \"camera\" would show the cubemap"})
        << o.output;
}

// The words of each GPU feature line, with every feature present and with none.
TEST(GpuFeatureLines, NameEachFeatureAndWhatPuddleDoesWithoutIt) {
    gpu::Capabilities all;
    all.float_render_targets = all.half_float_render_targets = all.float_linear_filtering = true;
    all.timer_queries = all.external_images = all.anisotropic_filtering = true;
    std::vector<std::string> present;
    for (const app::GpuFeatureLine& f : app::gpu_feature_lines(all, true)) {
        EXPECT_TRUE(f.present) << f.text;
        present.push_back(f.text);
    }
    EXPECT_EQ(present, (std::vector<std::string>{
                           "float render targets (wave field in RG32F)",
                           "half-float render targets (HDR sky, surface)",
                           "filtering of 32-bit float textures",
                           "timer queries",
                           "external images (OES_EGL_image_external_essl3)",
                           "dmabuf import (EGL_EXT_image_dma_buf_import)",
                           "anisotropic filtering",
                       }));
    std::vector<std::string> missing;
    for (const app::GpuFeatureLine& f : app::gpu_feature_lines(gpu::Capabilities{}, false)) {
        EXPECT_FALSE(f.present) << f.text;
        missing.push_back(f.text);
    }
    EXPECT_EQ(missing,
              (std::vector<std::string>{
                  "float render targets (wave field in RG32F): missing; the wave field runs in fixed point "
                  "(RG32I), the same picture",
                  "half-float render targets (HDR sky, surface): missing; HDR skies are stored as RGBM, the "
                  "surface as RGBA8",
                  "filtering of 32-bit float textures: missing; not needed: Puddle never filters them",
                  "timer queries: missing; --stats and puddle-bench show CPU times only",
                  "external images (OES_EGL_image_external_essl3): missing; camera frames are copied",
                  "dmabuf import (EGL_EXT_image_dma_buf_import): missing; camera frames are copied "
                  "(glTexSubImage2D)",
                  "anisotropic filtering: missing; the ground is filtered trilinearly",
              }));
    // Each flag drives its own line: only the timer queries missing.
    gpu::Capabilities no_timer = all;
    no_timer.timer_queries = false;
    const auto lines = app::gpu_feature_lines(no_timer, true);
    for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i].present, i != 3) << lines[i].text;
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

// A preset that does not exist stops a start with exit 2, so --check must say so too: it said OK, and an
// installer who trusted it walked away from a screen that would not start. Both places name presets.
TEST(Check, APresetThatDoesNotExistIsToFixAtTopLevelAndInASchedule) {
    TempDir dir;
    for (const std::string& text :
         {std::string("preset = \"nosuch\"\n"), std::string("[[schedule]]\nfrom = \"00:00\"\nto = \"24:00\"\n"
                                                            "preset = \"nosuch\"\n")}) {
        const std::string cfg = dir.write("presets.toml", text);
        const CommandResult o = check("--gpio mock: --config " + cfg);
        EXPECT_EQ(o.exit_code, 2) << o.output;
        const auto config = sections(o.output)["[config]"];
        ASSERT_FALSE(config.empty()) << o.output;
        EXPECT_TRUE(config[0].starts_with("  FIX   ")) << config[0];
        EXPECT_TRUE(has(config[0], "nosuch")) << config[0];
        EXPECT_TRUE(has(o.output, "thing(s) to fix")) << o.output;
    }
}

// The schedule's section: the entries active now and the next transition in local time (a window of the
// whole day is active at any hour and ends at the next midnight).
TEST(Check, PrintsTheActiveScheduleEntriesAndTheNextTransition) {
    TempDir dir;
    const std::string cfg = dir.write(
        "night.toml",
        "[[schedule]]\nfrom = \"00:00\"\nto = \"24:00\"\nbrightness = 0.5\n[[schedule]]\ndays = \"mon-fri\"\n"
        "at = \"sunset\"\ndisplay = \"off\"\n[location]\nlatitude = 52.5\nlongitude = 13.4\n");
    const std::string dri = node_folder(dir, "dri", {});
    const std::string dev = node_folder(dir, "dev", {});
    const CommandResult o =
        check_here({"--gpio", "mock:", "--config", cfg}, {.dri_folder = dri, .video_folder = dev});
    const auto schedule = sections(o.output)["[schedule]"];
    ASSERT_EQ(schedule.size(), 3u) << o.output;
    // The zone the entries' times are read in comes first (a zone changed while running is re-read).
    EXPECT_TRUE(schedule[0].starts_with("  OK    time zone: ")) << schedule[0];
    EXPECT_TRUE(schedule[1].starts_with("  OK    2 entries; now (")) << schedule[1];
    EXPECT_TRUE(has(schedule[1], "): schedule[1] (daily from 00:00 to 24:00)")) << schedule[1];
    EXPECT_TRUE(schedule[2].starts_with("        next transition: schedule[")) << schedule[2];

    const std::string none = dir.write("none.toml", "[rain]\ndrop_count = 40\n");
    const CommandResult n =
        check_here({"--gpio", "mock:", "--config", none}, {.dri_folder = dri, .video_folder = dev});
    EXPECT_EQ(sections(n.output)["[schedule]"],
              std::vector<std::string>{"  --    no [[schedule]] tables: the config applies at all hours"});
}

// The clock's section: the kernel's synchronisation status (adjtimex, injected here), to fix when the
// config makes a wall screen of this one (wall.clock = "realtime"), merely noted otherwise.
TEST(Check, SaysWhetherTheClockIsSynchronisedAndThatAWallNeedsIt) {
    TempDir dir;
    const std::string wall = dir.write("wall.toml", "[wall]\nclock = \"realtime\"\n");
    const std::string alone = dir.write("alone.toml", "[rain]\ndrop_count = 40\n");
    const std::string dri = node_folder(dir, "dri", {});
    const std::string dev = node_folder(dir, "dev", {});
    const auto unsynchronised = [] { return systems::ClockSync{.maximum_error_us = 16'000'000}; };
    const auto synchronised = [] {
        return systems::ClockSync{.synchronised = true, .estimated_error_us = 120, .maximum_error_us = 8400};
    };
    auto clock_lines = [&](const std::string& cfg, std::function<systems::ClockSync()> sync) {
        const CommandResult o = check_here({"--gpio", "mock:", "--config", cfg},
                                           {.dri_folder = dri, .video_folder = dev, .clock_sync = sync});
        return sections(o.output)["[clock]"];
    };
    const auto wall_unsynced = clock_lines(wall, unsynchronised);
    ASSERT_EQ(wall_unsynced.size(), 2u);
    EXPECT_TRUE(wall_unsynced[0].starts_with("  FIX   system clock: NOT synchronised")) << wall_unsynced[0];
    EXPECT_TRUE(has(wall_unsynced[0], "maximum error 16000.0 ms")) << wall_unsynced[0];
    EXPECT_TRUE(has(wall_unsynced[0], "set up chrony or linuxptp")) << wall_unsynced[0];
    EXPECT_EQ(wall_unsynced[1], "        wall.clock = \"realtime\"");
    const auto alone_unsynced = clock_lines(alone, unsynchronised);
    ASSERT_EQ(alone_unsynced.size(), 2u);
    EXPECT_TRUE(alone_unsynced[0].starts_with("  --    system clock: NOT synchronised")) << alone_unsynced[0];
    EXPECT_EQ(alone_unsynced[1], "        wall.clock = \"frame\"");
    EXPECT_EQ(clock_lines(wall, synchronised)[0],
              "  OK    system clock: synchronised, estimated error 0.120 ms (maximum 8.4 ms)");
}

}  // namespace
}  // namespace puddle::test
