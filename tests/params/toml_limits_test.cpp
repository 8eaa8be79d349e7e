// Tests for src/params/toml_limits.hpp: the bounds every TOML file is checked against before toml++
// parses it (a 50 000-level dotted key used to overflow the parser's stack: SIGSEGV).
#include "params/toml_limits.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "params/config_loader.hpp"
#include "support/test_support.hpp"

namespace puddle::params {
namespace {

std::string deep_key(int levels) {
    std::string key = "a";
    for (int i = 1; i < levels; ++i) key += ".a";
    return key;
}

Error limit_error(std::string_view text) {
    auto r = check_toml_limits(text, "deep.toml");
    if (r) {
        ADD_FAILURE() << "within the limits, expected an error";
        return {};
    }
    EXPECT_EQ(r.error().code, ExitCode::Config);
    return r.error();
}

TEST(TomlLimits, ADeepDottedKeyIsRefusedBeforeParsingNamingLineLevelsAndLimit) {
    const std::string text = "# a screen\n[rain]\n" + deep_key(50000) + " = 1\n";
    EXPECT_EQ(limit_error(text).message, "config: deep.toml:3: key nests 50001 levels; the limit is 16");
    // Through the config parser too (this crashed the process before).
    auto r = parse_config(text, "deep.toml");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "config: deep.toml:3: key nests 50001 levels; the limit is 16");
}

TEST(TomlLimits, DeepTableHeadersAndArraysOfTablesAreRefused) {
    EXPECT_EQ(limit_error("[" + deep_key(50000) + "]\nx = 1\n").message,
              "config: deep.toml:1: table header nests 50000 levels; the limit is 16");
    EXPECT_EQ(limit_error("\n[[" + deep_key(16) + "]]\n").message,
              "config: deep.toml:2: table header nests 17 levels; the limit is 16");
    // Header and key add up: 10 + 7 levels.
    EXPECT_EQ(limit_error("[" + deep_key(10) + "]\n" + deep_key(7) + " = 1\n").message,
              "config: deep.toml:2: key nests 17 levels; the limit is 16");
}

TEST(TomlLimits, DeepArraysAndInlineTablesAreRefused) {
    EXPECT_EQ(
        limit_error("[s]\nk = " + std::string(15, '[') + std::string(15, ']') + "\n").message,
        "config: deep.toml:2: value nests more than 16 levels (arrays or inline tables); the limit is 16");
    EXPECT_EQ(limit_error("[s]\nk = { " + deep_key(15) + " = 1 }\n").message,
              "config: deep.toml:2: key nests 17 levels; the limit is 16");
    // Each inline table's key adds its own levels.
    std::string nested = "1";
    for (int i = 0; i < 20; ++i) nested = "{ a = " + nested + " }";
    EXPECT_EQ(limit_error("k = " + nested + "\n").message,
              "config: deep.toml:1: key nests 17 levels; the limit is 16");
}

TEST(TomlLimits, ExactlyAtTheLimitIsFine) {
    EXPECT_TRUE(check_toml_limits("[" + deep_key(8) + "]\n" + deep_key(8) + " = 1\n", "ok.toml"));
    EXPECT_TRUE(
        check_toml_limits("[s]\nk = " + std::string(14, '[') + std::string(14, ']') + "\n", "ok.toml"));
    EXPECT_TRUE(check_toml_limits("[s]\n" + std::string(256, 'k') + " = 1\n", "ok.toml"));
}

TEST(TomlLimits, LongKeysLinesAndFilesAreRefused) {
    EXPECT_EQ(limit_error("[s]\n" + std::string(257, 'k') + " = 1\n").message,
              "config: deep.toml:2: key is 257 bytes long; the limit is 256");
    EXPECT_EQ(limit_error("[\"" + std::string(300, 'h') + "\"]\n").message,
              "config: deep.toml:1: table header is 302 bytes long; the limit is 256");
    EXPECT_EQ(limit_error("[s]\n\nk = \"" + std::string(70000, 'x') + "\"\n").message,
              "config: deep.toml:3: line is 70006 bytes long; the limit is 65536");
    std::string huge;
    while (huge.size() <= toml_limits.max_bytes) huge += "# a comment line that repeats\n";
    EXPECT_EQ(limit_error(huge).message,
              fmt::format("config: deep.toml: {} bytes; the limit is 1048576 bytes (1 MiB)", huge.size()));
}

TEST(TomlLimits, StringsAndCommentsDoNotCountAsNesting) {
    // Brackets, dots and quotes inside strings and comments are text, also across lines.
    const std::string text =
        "[s] # [[[[[[[[[[[[[[[[[[[[ a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q\n"
        "a = \"[[[[[[[[[[[[[[[[[[[[ \\\" a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a\"\n"
        "b = '''\n[[[[[[[[[[[[[[[[[[[[\na.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a.a = 1\n'''\n"
        "c = \"\"\"\n[x.x.x.x.x.x.x.x.x.x.x.x.x.x.x.x.x.x]\n\\\"\"\" \"\"\"\n"
        "d = [ \"]]]\", '[[[', { e = \"}\" } ]\n";
    auto r = check_toml_limits(text, "strings.toml");
    EXPECT_TRUE(r) << r.error().message;
}

TEST(TomlLimits, TheShippedConfigAndPresetsAreWellWithinTheLimits) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(PUDDLE_SOURCE_DIR "/config")) {
        if (entry.path().extension() != ".toml") continue;
        auto text = read_toml_file(entry.path().string());
        ASSERT_TRUE(text) << text.error().message;
        auto r = check_toml_limits(*text, entry.path().string());
        EXPECT_TRUE(r) << r.error().message;
    }
}

TEST(TomlLimits, ReadingStopsOneBytePastTheLimit) {
    test::TempDir dir;
    const std::string big = dir.write("big.toml", std::string(toml_limits.max_bytes + 4096, '#'));
    auto r = read_toml_file(big);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_EQ(r.error().message, "config: " + big + ": larger than 1 MiB; the limit is 1048576 bytes");
    // An endless source (a character device named as the config) is not read at all.
    auto zero = read_toml_file("/dev/zero");
    ASSERT_FALSE(zero);
    EXPECT_EQ(zero.error().message, "config: /dev/zero: is a character device, not a file");
    auto config = load_config_file(big);
    ASSERT_FALSE(config);
    EXPECT_EQ(config.error().message, r.error().message);
}

// A FIFO named as the config (or a preset, or the state file) once left the program waiting in open()
// for a writer: at start-up for ever, and on a running display with the frames and SIGTERM stuck.
TEST(TomlLimits, AFifoOrAFolderIsRefusedAtOnceWithoutWaitingForAWriter) {
    test::TempDir dir;
    const std::string fifo = (dir / "puddle.toml").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    auto r = read_toml_file(fifo);  // before: blocked here until a writer came
    ASSERT_FALSE(r);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_EQ(r.error().code, ExitCode::Config);
    EXPECT_EQ(r.error().message, "config: " + fifo + ": is a FIFO, not a file");
    auto folder = read_toml_file(dir.path().string());
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error().message, "config: " + dir.path().string() + ": is a folder, not a file");
}

}  // namespace
}  // namespace puddle::params
