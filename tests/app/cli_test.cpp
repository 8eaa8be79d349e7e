// Tests for src/app/cli.hpp: parse_command_line's options, defaults and errors.
#include "app/cli.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace puddle::app {
namespace {

Result<CliOptions> parse(std::initializer_list<const char*> args) {
    std::vector<const char*> argv{"puddle"};
    argv.insert(argv.end(), args.begin(), args.end());
    return parse_command_line(static_cast<int>(argv.size()), argv.data());
}

CliOptions parse_ok(std::initializer_list<const char*> args) {
    auto r = parse(args);
    if (!r) {
        ADD_FAILURE() << r.error().message;
        return {};
    }
    return *r;
}

// The error of a command line that must be rejected.
Error parse_error(std::initializer_list<const char*> args) {
    auto r = parse(args);
    if (r) {
        ADD_FAILURE() << "accepted, expected an error";
        return {};
    }
    return r.error();
}

bool has_text(const std::string& text, std::string_view needle) {
    return text.find(needle) != std::string::npos;
}

TEST(Cli, Defaults) {
    const CliOptions o = parse_ok({});
    EXPECT_EQ(o.config_path, "");
    EXPECT_TRUE(o.sets.empty());
    EXPECT_FALSE(o.list_params);
    EXPECT_FALSE(o.print_config);
    EXPECT_EQ(o.display.backend, platform::BackendKind::Auto);
    EXPECT_EQ(o.display.size, glm::ivec2(0, 0));
    EXPECT_FALSE(o.display.fullscreen);
    EXPECT_FALSE(o.frames.has_value());
    EXPECT_EQ(o.screenshot, "");
    EXPECT_FALSE(o.seed.has_value());
    EXPECT_EQ(o.fps_cap, 0.0);
    EXPECT_FALSE(o.fixed_step);
    EXPECT_EQ(o.log_level, "info");
}

TEST(Cli, Backend) {
    EXPECT_EQ(parse_ok({"--backend", "auto"}).display.backend, platform::BackendKind::Auto);
    EXPECT_EQ(parse_ok({"--backend", "kms"}).display.backend, platform::BackendKind::Kms);
    EXPECT_EQ(parse_ok({"--backend", "window"}).display.backend, platform::BackendKind::Window);
    EXPECT_EQ(parse_ok({"--backend", "headless"}).display.backend, platform::BackendKind::Headless);
    EXPECT_EQ(parse_ok({"-b", "headless"}).display.backend, platform::BackendKind::Headless);
    EXPECT_EQ(parse_ok({"--backend=kms"}).display.backend, platform::BackendKind::Kms);

    const Error e = parse_error({"--backend", "wayland"});
    EXPECT_EQ(e.code, ExitCode::Config);
    EXPECT_TRUE(has_text(e.message, "wayland")) << e.message;
    EXPECT_TRUE(has_text(e.message, "(see puddle --help)")) << e.message;
}

TEST(Cli, Size) {
    EXPECT_EQ(parse_ok({"--size", "1280x720"}).display.size, glm::ivec2(1280, 720));
    EXPECT_EQ(parse_ok({"--size", "1920X1080"}).display.size, glm::ivec2(1920, 1080));
    EXPECT_EQ(parse_ok({"--size", "16x16"}).display.size, glm::ivec2(16, 16));
    EXPECT_EQ(parse_ok({"--size", "16384x16384"}).display.size, glm::ivec2(16384, 16384));
}

TEST(Cli, BadSizesAreConfigErrors) {
    for (const char* bad : {"1280", "1280x", "x720", "axb", "1280*720", "1280x720x3", "1280x720 ", "8x8",
                            "15x720", "1280x16385", "0x0"}) {
        const Error e = parse_error({"--size", bad});
        EXPECT_EQ(e.code, ExitCode::Config) << bad;
        EXPECT_EQ(static_cast<int>(e.code), 2);
        EXPECT_EQ(e.message,
                  fmt::format("--size {}: expected WIDTHxHEIGHT, e.g. 1280x720 (16 to 16384 each)", bad));
    }
}

TEST(Cli, SetIsRepeatableAndKeepsOrder) {
    const CliOptions o =
        parse_ok({"--set", "rain.drop_count=20", "-s", "water.turbidity=0.2", "--set", "rain.drop_count=30"});
    EXPECT_EQ(o.sets,
              (std::vector<std::string>{"rain.drop_count=20", "water.turbidity=0.2", "rain.drop_count=30"}));
}

// A new user's first try was --set preset=downpour: it is --preset downpour, as -p is.
TEST(Cli, PresetByItsOptionOrAsASet) {
    EXPECT_EQ(parse_ok({"--preset", "downpour"}).preset, "downpour");
    EXPECT_EQ(parse_ok({"-p", "mirror"}).preset, "mirror");
    const CliOptions o = parse_ok({"--set", "rain.drop_count=20", "--set", "preset=downpour"});
    EXPECT_EQ(o.preset, "downpour");
    EXPECT_EQ(o.sets, (std::vector<std::string>{"rain.drop_count=20"})) << "no parameter called preset";
    EXPECT_EQ(parse_ok({}).preset, "");
}

TEST(Cli, SetValuesAreNotCheckedHere) {
    // --set is validated later, against the registry, where the message can name the parameter.
    EXPECT_EQ(parse_ok({"--set", "no.such=1"}).sets, (std::vector<std::string>{"no.such=1"}));
}

TEST(Cli, CameraTakesADeviceOrAMockSource) {
    EXPECT_EQ(parse_ok({"--camera", "/dev/video2"}).camera, "/dev/video2");
    EXPECT_EQ(parse_ok({"--camera", "mock:/tmp/room.png"}).camera, "mock:/tmp/room.png");
    EXPECT_EQ(parse_ok({}).camera, "");
}

TEST(Cli, Frames) {
    EXPECT_EQ(parse_ok({"--frames", "300"}).frames, 300L);
    EXPECT_EQ(parse_ok({"-n", "1"}).frames, 1L);
    EXPECT_EQ(parse_ok({"--frames", "0"}).frames, 0L);  // run until stopped
    EXPECT_EQ(parse_error({"--frames", "many"}).code, ExitCode::Config);
    EXPECT_EQ(parse_error({"--frames", "-5"}).code, ExitCode::Config);
}

TEST(Cli, Seed) {
    EXPECT_EQ(parse_ok({"--seed", "42"}).seed, 42);
    EXPECT_EQ(parse_ok({"--seed", "0"}).seed, 0);
    EXPECT_EQ(parse_ok({"--seed", "2147483647"}).seed, 2147483647);
    EXPECT_EQ(parse_error({"--seed", "-1"}).code, ExitCode::Config);
    EXPECT_EQ(parse_error({"--seed", "abc"}).code, ExitCode::Config);
}

TEST(Cli, OtherOptions) {
    const CliOptions o =
        parse_ok({"--config", "/etc/puddle/puddle.toml", "--list-params", "--print-config", "--fullscreen",
                  "--screenshot", "out.png", "--fps-cap", "30", "--log-level", "debug"});
    EXPECT_EQ(o.config_path, "/etc/puddle/puddle.toml");
    EXPECT_TRUE(o.list_params);
    EXPECT_TRUE(o.print_config);
    EXPECT_TRUE(o.display.fullscreen);
    EXPECT_EQ(o.screenshot, "out.png");
    EXPECT_EQ(o.fps_cap, 30.0);
    EXPECT_EQ(o.log_level, "debug");
    EXPECT_EQ(parse_ok({"-c", "a.toml"}).config_path, "a.toml");
    EXPECT_EQ(parse_error({"--log-level", "loud"}).code, ExitCode::Config);
    EXPECT_EQ(parse_error({"--fps-cap", "5000"}).code, ExitCode::Config);
    EXPECT_EQ(parse_error({"--fps-cap", "nan"}).code, ExitCode::Config);  // CLI::Range let it through
    EXPECT_TRUE(parse_ok({"--fixed-step"}).fixed_step);
}

TEST(Cli, Stats) {
    EXPECT_EQ(parse_ok({}).stats_every, 0.0);  // off
    EXPECT_EQ(parse_ok({"--stats"}).stats_every, 5.0);
    EXPECT_EQ(parse_ok({"--stats", "2"}).stats_every, 2.0);
    EXPECT_EQ(parse_ok({"--stats", "--frames", "3"}).frames, 3L);
    EXPECT_EQ(parse_error({"--stats", "0"}).code, ExitCode::Config);
}

TEST(Cli, HelpAndVersionExitWithOk) {
    testing::internal::CaptureStdout();
    auto help = parse({"--help"});
    const std::string help_text = testing::internal::GetCapturedStdout();
    ASSERT_FALSE(help);
    EXPECT_EQ(help.error().code, ExitCode::Ok);
    EXPECT_TRUE(has_text(help_text, "--set")) << help_text;
    EXPECT_TRUE(has_text(help_text, "--list-params")) << help_text;
    EXPECT_TRUE(has_text(help_text, "--preset")) << help_text;
    EXPECT_TRUE(has_text(help_text, "--set preset=NAME is the same")) << help_text;

    testing::internal::CaptureStdout();
    auto short_help = parse({"-h"});
    testing::internal::GetCapturedStdout();
    ASSERT_FALSE(short_help);
    EXPECT_EQ(short_help.error().code, ExitCode::Ok);

    testing::internal::CaptureStdout();
    auto version = parse({"--version"});
    const std::string version_text = testing::internal::GetCapturedStdout();
    ASSERT_FALSE(version);
    EXPECT_EQ(version.error().code, ExitCode::Ok);
    EXPECT_TRUE(version_text.starts_with("puddle ")) << version_text;
}

TEST(Cli, UnknownFlagIsAConfigError) {
    const Error e = parse_error({"--bogus"});
    EXPECT_EQ(e.code, ExitCode::Config);
    EXPECT_EQ(static_cast<int>(e.code), 2);
    EXPECT_TRUE(has_text(e.message, "--bogus")) << e.message;
    EXPECT_TRUE(e.message.starts_with("puddle: ")) << e.message;

    EXPECT_EQ(parse_error({"stray"}).code, ExitCode::Config);
    EXPECT_EQ(parse_error({"--size"}).code, ExitCode::Config);  // missing value
}

}  // namespace
}  // namespace puddle::app
