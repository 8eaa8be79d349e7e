// Issue 15, faults 2 and 3, through the real binary: a file past the input limits and a number past its
// parameter's range stop start-up with exit code 2 and one line naming the file, the line and the limit.
// Only --print-config is run, so no display or GPU is needed.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace puddle::test {
namespace {

bool has_line(const std::string& output, const std::string& text) {
    return output.find(text) != std::string::npos;
}

std::string deep_key(int levels) {
    std::string key = "a";
    for (int i = 1; i < levels; ++i) key += ".a";
    return key;
}

TEST(InputFiles, ADeepDottedKeyOrTableHeaderExitsWith2NamingTheFileAndTheLimit) {
    TempDir dir;
    const std::string key = dir.write("key.toml", deep_key(50001) + " = 1\n");  // was SIGSEGV, exit 139
    const auto k = run_puddle("--config " + key + " --print-config");
    EXPECT_EQ(k.exit_code, 2) << k.output;
    EXPECT_TRUE(has_line(k.output, "config: " + key + ":1: key nests 50001 levels; the limit is 16"))
        << k.output;

    const std::string header = dir.write("header.toml", "# one\n[" + deep_key(50000) + "]\n");
    const auto h = run_puddle("--config " + header + " --print-config");
    EXPECT_EQ(h.exit_code, 2) << h.output;
    EXPECT_TRUE(
        has_line(h.output, "config: " + header + ":2: table header nests 50000 levels; the limit is 16"))
        << h.output;
}

TEST(InputFiles, APresetPastTheLimitsExitsWith2NamingThePresetFile) {
    TempDir dir;
    std::filesystem::create_directories(dir / "presets");
    const std::string preset = dir.write("presets/deep.toml", "[rain]\n" + deep_key(50000) + " = 1\n");
    const std::string config = dir.write("puddle.toml", "preset = \"deep\"\n");
    const auto r = run_puddle("--config " + config + " --print-config");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    // One prefix, both places: the line that chose the preset and the preset's own line.
    EXPECT_TRUE(has_line(r.output, "error: config: " + config + ":1: preset = \"deep\": " + preset +
                                       ":2: key nests 50001 levels; the limit is 16"))
        << r.output;
}

TEST(InputFiles, ASeedPastIntsRangeExitsWith2FromTheFileAndFromSet) {
    TempDir dir;
    const std::string config = dir.write("screen.toml", "# screen 1\n[rain]\nseed = 4294967297\n");
    const auto f = run_puddle("--config " + config + " --print-config");  // was exit 0 with 2147483647
    EXPECT_EQ(f.exit_code, 2) << f.output;
    EXPECT_TRUE(
        has_line(f.output, "config: " + config +
                               ":3: rain.seed = 4294967297 is out of range: allowed an integer from 0 to "
                               "2147483647"))
        << f.output;
    const auto s = run_puddle("--set rain.seed=4294967297 --print-config");
    EXPECT_EQ(s.exit_code, 2) << s.output;
    EXPECT_TRUE(has_line(s.output,
                         "--set: rain.seed = 4294967297 is out of range: allowed an integer from 0 to "
                         "2147483647"))
        << s.output;
}

TEST(InputFiles, TheVideoWallCasesExitWith2) {
    const std::string dir = std::string(PUDDLE_SHARED_DIR) + "/cases/config";
    if (!std::filesystem::exists(dir + "/screen1.toml"))
        GTEST_SKIP() << "needs ../shared/cases/config (absent)";
    for (const char* screen : {"screen1.toml", "screen2.toml"}) {
        const auto r = run_puddle("--config " + dir + "/" + screen + " --print-config");
        EXPECT_EQ(r.exit_code, 2) << screen << "\n" << r.output;
        EXPECT_TRUE(has_line(r.output, "config: " + dir + "/" + screen + ":3: rain.seed = ")) << r.output;
        EXPECT_TRUE(has_line(r.output, "is out of range: allowed an integer from 0 to 2147483647"))
            << r.output;
    }
}

// A FIFO as the config: exit 2 with one line at once (the program used to wait in open() for a writer,
// for ever; the state file and presets are read the same way, see TomlLimits).
TEST(InputFiles, AFifoAsTheConfigExitsWith2AtOnce) {
    TempDir dir;
    const std::string fifo = (dir / "puddle.toml").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto r = run_puddle("--config " + fifo + " --print-config");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(has_line(r.output, "config: " + fifo + ": is a FIFO, not a file")) << r.output;
}

}  // namespace
}  // namespace puddle::test
