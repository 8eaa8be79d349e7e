// inotify on the config's folder: in-place writes, editors' rename-over, delete and re-create.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "params/config_watcher.hpp"
#include "support/test_support.hpp"

namespace puddle::params {
namespace {

using Change = ConfigWatcher::Change;

TEST(ConfigWatcher, SeesAWriteInPlace) {
    test::TempDir dir;
    const std::string path = dir.write("puddle.toml", "[rain]\n");
    auto w = ConfigWatcher::watch(path);
    ASSERT_TRUE(w) << w.error().message;
    EXPECT_EQ(w->poll(), Change::None);
    std::ofstream(path) << "[rain]\ndrop_count = 3\n";
    EXPECT_EQ(w->poll(), Change::Written) << "seen as soon as the file is closed, no waiting";
    EXPECT_EQ(w->poll(), Change::None);
}

TEST(ConfigWatcher, SeesARenameOverTheFileAsEditorsSave) {
    test::TempDir dir;
    const std::string path = dir.write("puddle.toml", "[rain]\n");
    auto w = ConfigWatcher::watch(path);
    ASSERT_TRUE(w);
    const std::string temp = dir.write(".puddle.toml.swp", "[rain]\ndrop_count = 4\n");
    EXPECT_EQ(w->poll(), Change::None) << "other files in the folder are not the config";
    std::filesystem::rename(temp, path);
    EXPECT_EQ(w->poll(), Change::Written);
    // And again: the watch survives the file being replaced.
    std::filesystem::rename(dir.write("new", "[rain]\n"), path);
    EXPECT_EQ(w->poll(), Change::Written);
}

TEST(ConfigWatcher, DeleteThenRecreate) {
    test::TempDir dir;
    const std::string path = dir.write("puddle.toml", "[rain]\n");
    auto w = ConfigWatcher::watch(path);
    ASSERT_TRUE(w);
    std::filesystem::remove(path);
    EXPECT_EQ(w->poll(), Change::Removed);
    dir.write("puddle.toml", "[rain]\ndrop_count = 5\n");
    EXPECT_EQ(w->poll(), Change::Written);
}

TEST(ConfigWatcher, AMissingFolderIsAnErrorNamingIt) {
    auto w = ConfigWatcher::watch("/nonexistent-puddle-dir/puddle.toml");
    ASSERT_FALSE(w);
    EXPECT_NE(w.error().message.find("/nonexistent-puddle-dir"), std::string::npos) << w.error().message;
}

}  // namespace
}  // namespace puddle::params
