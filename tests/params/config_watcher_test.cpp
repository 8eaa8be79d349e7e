// inotify on the config's folder: in-place writes, editors' rename-over, delete and re-create, and
// configs that are symbolic links (the target edited, the link re-pointed, chains of links).
#include "params/config_watcher.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

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

// /etc/puddle/puddle.toml -> ../opt/signage/puddle.toml, as config management and read-only images ship it.
struct LinkedConfig {
    test::TempDir dir;
    std::filesystem::path etc = dir / "etc/puddle";
    std::filesystem::path opt = dir / "opt/signage";
    std::filesystem::path link = etc / "puddle.toml";
    std::filesystem::path target = opt / "puddle.toml";
    LinkedConfig() {
        std::filesystem::create_directories(etc);
        std::filesystem::create_directories(opt);
        std::ofstream(target) << "[rain]\n";
        std::filesystem::create_symlink("../../opt/signage/puddle.toml",
                                        link);  // relative, as ln -s makes them
    }
};

void write_file(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

// `ln -sfn NEW LINK`, run as a person would.
void repoint(const std::filesystem::path& link, const std::string& new_target) {
    const std::string cmd = "ln -sfn '" + new_target + "' '" + link.string() + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

TEST(ConfigWatcher, SeesAnEditOfASymlinkedConfigsTarget) {
    LinkedConfig c;
    auto w = ConfigWatcher::watch(c.link.string());
    ASSERT_TRUE(w) << w.error().message;
    ASSERT_EQ(w->chain().size(), 2u) << "the link's folder and the target's";
    EXPECT_EQ(w->poll(), Change::None);
    write_file(c.target, "[rain]\ndrop_count = 3\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the target was edited in place";
    write_file(c.opt / ".puddle.toml.swp", "[rain]\ndrop_count = 4\n");
    std::filesystem::rename(c.opt / ".puddle.toml.swp", c.target);
    EXPECT_EQ(w->poll(), Change::Written) << "the target was replaced by an editor's rename";
    write_file(c.opt / "other.toml", "x");
    EXPECT_EQ(w->poll(), Change::None) << "other files beside the target are not the config";
}

TEST(ConfigWatcher, FollowsALinkRepointedWithLnSfn) {
    LinkedConfig c;
    const auto next = c.opt / "night.toml";
    write_file(next, "[rain]\ndrop_count = 7\n");
    auto w = ConfigWatcher::watch(c.link.string());
    ASSERT_TRUE(w) << w.error().message;
    repoint(c.link, next.string());
    EXPECT_EQ(w->poll(), Change::Written) << "the link now leads to another file";
    write_file(next, "[rain]\ndrop_count = 8\n");
    EXPECT_EQ(w->poll(), Change::Written) << "edits of the new target are seen";
    write_file(c.target, "[rain]\ndrop_count = 9\n");
    EXPECT_EQ(w->poll(), Change::None) << "the old target is no longer the config";
}

TEST(ConfigWatcher, FollowsAChainOfLinksAndItsMiddleLink) {
    LinkedConfig c;
    // etc/puddle/puddle.toml -> opt/signage/puddle.toml -> releases/a/puddle.toml: the middle link moves.
    const auto releases = c.dir / "releases";
    std::filesystem::create_directories(releases / "a");
    std::filesystem::create_directories(releases / "b");
    write_file(releases / "a/puddle.toml", "[rain]\ndrop_count = 1\n");
    write_file(releases / "b/puddle.toml", "[rain]\ndrop_count = 2\n");
    std::filesystem::remove(c.target);
    std::filesystem::create_symlink(releases / "a/puddle.toml", c.target);
    auto w = ConfigWatcher::watch(c.link.string());
    ASSERT_TRUE(w) << w.error().message;
    ASSERT_EQ(w->chain().size(), 3u);
    write_file(releases / "a/puddle.toml", "[rain]\ndrop_count = 3\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the end of the chain was edited";
    repoint(c.target, (releases / "b/puddle.toml").string());
    EXPECT_EQ(w->poll(), Change::Written) << "the middle link was re-pointed";
    write_file(releases / "b/puddle.toml", "[rain]\ndrop_count = 4\n");
    EXPECT_EQ(w->poll(), Change::Written);
    write_file(releases / "a/puddle.toml", "[rain]\ndrop_count = 5\n");
    EXPECT_EQ(w->poll(), Change::None);
}

TEST(ConfigWatcher, ALinkThatLeadsNowhereIsARemovalUntilItLeadsSomewhere) {
    LinkedConfig c;
    auto w = ConfigWatcher::watch(c.link.string());
    ASSERT_TRUE(w) << w.error().message;
    repoint(c.link, (c.opt / "missing.toml").string());
    EXPECT_EQ(w->poll(), Change::Removed);
    write_file(c.opt / "missing.toml", "[rain]\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the dangling link's target appeared";
    std::filesystem::remove(c.opt / "missing.toml");
    EXPECT_EQ(w->poll(), Change::Removed) << "and went again";
}

TEST(ConfigWatcher, AFileReplacedByALinkIsFollowed) {
    test::TempDir dir;
    const std::string path = dir.write("puddle.toml", "[rain]\n");
    std::filesystem::create_directories(dir / "managed");
    write_file(dir / "managed/puddle.toml", "[rain]\ndrop_count = 6\n");
    auto w = ConfigWatcher::watch(path);
    ASSERT_TRUE(w);
    repoint(path, (dir / "managed/puddle.toml").string());
    EXPECT_EQ(w->poll(), Change::Written);
    write_file(dir / "managed/puddle.toml", "[rain]\ndrop_count = 7\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the new link's target is watched from now on";
}

TEST(ConfigWatcher, AMissingFolderIsAnErrorNamingIt) {
    auto w = ConfigWatcher::watch("/nonexistent-puddle-dir/puddle.toml");
    ASSERT_FALSE(w);
    EXPECT_NE(w.error().message.find("/nonexistent-puddle-dir"), std::string::npos) << w.error().message;
}

}  // namespace
}  // namespace puddle::params
