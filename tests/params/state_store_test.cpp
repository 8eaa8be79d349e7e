// The knob state file: atomic saves, crash safety, corrupt files moved aside.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "params/state_store.hpp"
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
    EXPECT_TRUE(loaded.warning.empty());
    ASSERT_EQ(loaded.state->entries.size(), 1u);
    EXPECT_EQ(loaded.state->entries[0].id, ParamId::rain_intensity);
}

TEST(StateStore, NoFileIsNoStateAndNoWarning) {
    test::TempDir dir;
    auto loaded = StateStore((dir / "state.toml").string()).load();
    EXPECT_FALSE(loaded.state);
    EXPECT_TRUE(loaded.warning.empty());
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

TEST(StateStore, ACorruptFileIsMovedAsideWithAWarning) {
    test::TempDir dir;
    const std::string path = dir.write("state.toml", "[rain\nintensity = \x01\x02 garbage");
    auto loaded = StateStore(path).load();
    EXPECT_FALSE(loaded.state);
    EXPECT_NE(loaded.warning.find(path), std::string::npos) << loaded.warning;
    EXPECT_NE(loaded.warning.find(".corrupt"), std::string::npos) << loaded.warning;
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_TRUE(std::filesystem::exists(path + ".corrupt"));
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
