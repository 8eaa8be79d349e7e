// The knob state file: atomic saves, crash safety, corrupt files moved aside.
#include "params/state_store.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "support/test_support.hpp"

namespace puddle::params {
namespace {

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(StateStore, SavesAndLoads) {
    test::TempDir dir;
    StateStore store((dir / "sub" / "state.toml").string());  // makes the folder
    ASSERT_TRUE(store.save("[rain]\nintensity = 0.7\n"));
    auto loaded = store.load();
    ASSERT_TRUE(loaded.state);
    EXPECT_TRUE(loaded.problems.empty());
    ASSERT_EQ(loaded.state->entries.size(), 1u);
    EXPECT_EQ(loaded.state->entries[0].id, ParamId::rain_intensity);
}

TEST(StateStore, NoFileIsNoStateAndNoWarning) {
    test::TempDir dir;
    auto loaded = StateStore((dir / "state.toml").string()).load();
    EXPECT_FALSE(loaded.state);
    EXPECT_TRUE(loaded.problems.empty());
}

TEST(StateStore, ACrashBetweenWriteAndRenameLeavesThePreviousStateIntact) {
    test::TempDir dir;
    StateStore store((dir / "state.toml").string());
    ASSERT_TRUE(store.save("[rain]\nintensity = 0.7\n"));
    // The new state is completely written to the temporary file, then the process dies.
    auto temp = store.write_temporary("[rain]\nintensity = 0.9\n");
    ASSERT_TRUE(temp);
    EXPECT_EQ(read(*temp), "[rain]\nintensity = 0.9\n");
    EXPECT_EQ(read(store.path()), "[rain]\nintensity = 0.7\n");
    auto loaded = StateStore(store.path()).load();
    ASSERT_TRUE(loaded.state);
    EXPECT_FLOAT_EQ(std::get<float>(loaded.state->entries[0].value), 0.7f);
    // The next save replaces the leftover temporary file.
    ASSERT_TRUE(store.save("[rain]\nintensity = 0.8\n"));
    EXPECT_FALSE(std::filesystem::exists(*temp));
    EXPECT_EQ(read(store.path()), "[rain]\nintensity = 0.8\n");
}

TEST(StateStore, AFileThatIsNotTomlGivesNoStateAndOneProblemAndIsLeftInPlace) {
    test::TempDir dir;
    const std::string text = "[rain\nintensity = \x01\x02 garbage";
    const std::string path = dir.write("state.toml", text);
    auto loaded = StateStore(path).load();
    EXPECT_FALSE(loaded.state);
    ASSERT_EQ(loaded.problems.size(), 1u);
    // One line in the state's own words: no "(config: PATH...)" inside, and the line it failed at.
    EXPECT_TRUE(loaded.problems[0].starts_with("state: " + path + ":1: ")) << loaded.problems[0];
    EXPECT_TRUE(loaded.problems[0].ends_with("; no saved value could be read (the config's values apply)"))
        << loaded.problems[0];
    EXPECT_EQ(loaded.problems[0].find("config: "), std::string::npos) << loaded.problems[0];
    EXPECT_EQ(loaded.problems[0].find('\x01'), std::string::npos) << "control characters are not quoted";
    EXPECT_EQ(read(path), text) << "load() reads only";
}

// A hand edit that breaks the TOML on line 3 keeps the value on line 2 (it used to lose every value).
TEST(StateStore, AFileThatStopsBeingTomlKeepsTheKeysBeforeTheBreak) {
    test::TempDir dir;
    const std::string path = dir.write("state.toml", "[rain]\nintensity = 0.5\n[look\nvignette = 1.1\n");
    auto loaded = StateStore(path).load();
    ASSERT_TRUE(loaded.state);
    ASSERT_EQ(loaded.state->entries.size(), 1u);
    EXPECT_EQ(loaded.state->entries[0].id, ParamId::rain_intensity);
    EXPECT_EQ(std::get<float>(loaded.state->entries[0].value), 0.5f);
    ASSERT_EQ(loaded.problems.size(), 1u);
    EXPECT_NE(loaded.problems[0].find(path + ":3: "), std::string::npos) << loaded.problems[0];
    EXPECT_TRUE(loaded.problems[0].ends_with("the keys from line 3 on are dropped")) << loaded.problems[0];
}

// A key past the length limit on line 4 (a hand edit, a stray paste) kept none of the values before it.
TEST(StateStore, AKeyPastTheLimitsKeepsTheValuesBeforeIt) {
    test::TempDir dir;
    const std::string path =
        dir.write("state.toml", "[rain]\nintensity = 0.5\nspeed = 0.7\n" + std::string(300, 'k') + " = 1\n");
    auto loaded = StateStore(path).load();
    ASSERT_TRUE(loaded.state) << (loaded.problems.empty() ? "" : loaded.problems[0]);
    EXPECT_EQ(loaded.state->entries.size(), 2u);
    ASSERT_EQ(loaded.problems.size(), 1u);
    EXPECT_EQ(loaded.problems[0],
              "state: " + path +
                  ":4: key is 300 bytes long; the limit is 256; the keys from line 4 on are "
                  "dropped");
}

// toml++ stops at a number too big for 64 bits without naming the key; the line names it, with the
// parameter's range, as for any other out-of-range value, and the values above it are kept.
TEST(StateStore, ANumberTooBigForTomlIsNamedWithItsKeyAndRange) {
    test::TempDir dir;
    const std::string path =
        dir.write("state.toml", "[rain]\nintensity = 0.5\nseed = 99999999999999999999\n");
    auto loaded = StateStore(path).load();
    ASSERT_TRUE(loaded.state);
    ASSERT_EQ(loaded.state->entries.size(), 1u);
    ASSERT_EQ(loaded.problems.size(), 1u);
    EXPECT_EQ(loaded.problems[0],
              "state: " + path +
                  ":3: rain.seed = 99999999999999999999 is out of range: allowed an integer "
                  "from 0 to 2147483647; the keys from line 3 on are dropped");
}

// A FIFO named as the state file is reported, not waited on.
TEST(StateStore, AFifoIsAProblemNotAWait) {
    test::TempDir dir;
    const std::string fifo = (dir / "state.toml").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto loaded = StateStore(fifo).load();
    EXPECT_FALSE(loaded.state);
    ASSERT_EQ(loaded.problems.size(), 1u);
    EXPECT_NE(loaded.problems[0].find("is a FIFO, not a file"), std::string::npos) << loaded.problems[0];
}

// The set-aside names in `dir`, sorted.
std::vector<std::string> copies_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().starts_with("state.toml.bad-"))
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Issue 15, fault 5: one bad key threw away every saved knob value.
TEST(StateStore, OneBadKeyIsDroppedAndReportedAndEveryValidKeyIsKept) {
    test::TempDir dir;
    const std::string path =
        dir.write("state.toml",
                  "[rain]\nintensity = 0.8\nwind = 0.5\n[look]\nvignette = 1.2\n[water]\nturbidity = 2.5\n");
    auto loaded = StateStore(path).load();
    ASSERT_TRUE(loaded.state);
    ASSERT_EQ(loaded.state->entries.size(), 2u);
    EXPECT_EQ(loaded.state->entries[0].id, ParamId::rain_intensity);
    EXPECT_FLOAT_EQ(std::get<float>(loaded.state->entries[0].value), 0.8f);
    EXPECT_EQ(loaded.state->entries[1].id, ParamId::look_vignette);
    EXPECT_FLOAT_EQ(std::get<float>(loaded.state->entries[1].value), 1.2f);
    ASSERT_EQ(loaded.problems.size(), 2u);
    EXPECT_TRUE(loaded.problems[0].starts_with("state: " + path + ":3: unknown key 'rain.wind'"))
        << loaded.problems[0];
    EXPECT_TRUE(loaded.problems[0].ends_with("; dropped that value, kept the others")) << loaded.problems[0];
    EXPECT_EQ(loaded.problems[1],
              "state: " + path +
                  ":7: water.turbidity = 2.5 is out of range: allowed a number from 0 to 2 1/unit; "
                  "dropped that value, kept the others");
}

TEST(StateStore, TheSharedCasesKeepTheirGoodValues) {
    const std::string cases = std::string(PUDDLE_SHARED_DIR) + "/cases/state";
    if (!std::filesystem::exists(cases + "/state_one_out_of_range.toml"))
        GTEST_SKIP() << "needs ../shared/cases/state (absent)";
    for (const char* name : {"state_one_out_of_range.toml", "state_one_unknown_key.toml"}) {
        auto loaded = StateStore(cases + "/" + name).load();
        ASSERT_TRUE(loaded.state) << name;
        EXPECT_EQ(loaded.problems.size(), 1u) << name;
        std::vector<ParamId> kept;
        for (const auto& e : loaded.state->entries) kept.push_back(e.id);
        EXPECT_EQ(kept, (std::vector<ParamId>{ParamId::rain_intensity, ParamId::look_vignette})) << name;
    }
}

TEST(StateStore, SetAsideNeverOverwritesAnEarlierCopyAndKeepsTheNewestFive) {
    test::TempDir dir;
    StateStore store((dir / "state.toml").string());
    std::vector<std::string> made;
    for (int i = 1; i <= 7; ++i) {
        ASSERT_TRUE(store.save(fmt::format("# bad file {}\n[rain]\nwind = {}\n", i, i)));
        auto copy = store.set_aside();
        ASSERT_TRUE(copy) << copy.error().message;
        made.push_back(std::filesystem::path(*copy).filename().string());
        // Within one second the names differ by their sequence number, not the clock.
        EXPECT_TRUE(made.back().starts_with(fmt::format("state.toml.bad-{:04}-", i))) << made.back();
        EXPECT_EQ(read(*copy), fmt::format("# bad file {}\n[rain]\nwind = {}\n", i, i));
    }
    // The two oldest are gone; the five newest hold what each file held when it was set aside.
    EXPECT_EQ(copies_in(dir.path()), std::vector<std::string>(made.begin() + 2, made.end()));
    for (int i = 3; i <= 7; ++i)
        EXPECT_EQ(read((dir / made[static_cast<std::size_t>(i - 1)]).string()),
                  fmt::format("# bad file {}\n[rain]\nwind = {}\n", i, i));
    // Saving after a set-aside replaces the state, not the copy.
    ASSERT_TRUE(store.save("[rain]\nintensity = 0.5\n"));
    EXPECT_EQ(read((dir / made.back()).string()), "# bad file 7\n[rain]\nwind = 7\n");
}

TEST(StateStore, DefaultPathFollowsSystemdThenXdg) {
    ::setenv("STATE_DIRECTORY", "/var/lib/puddle", 1);
    EXPECT_EQ(StateStore::default_path(), "/var/lib/puddle/state.toml");
    ::unsetenv("STATE_DIRECTORY");
    ::setenv("XDG_STATE_HOME", "/home/x/.state", 1);
    EXPECT_EQ(StateStore::default_path(), "/home/x/.state/puddle/state.toml");
    ::unsetenv("XDG_STATE_HOME");
}

}  // namespace
}  // namespace puddle::params
