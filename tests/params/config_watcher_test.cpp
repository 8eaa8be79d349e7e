// inotify on the config's folder: in-place writes, editors' rename-over, delete and re-create, and
// configs that are symbolic links (the target edited, the link re-pointed, chains of links, a linked
// folder flipped), folders removed and made again, and things that are not files in the config's place.
#include "params/config_watcher.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "params/config_loader.hpp"
#include "support/test_support.hpp"

namespace puddle::params {

// Names in failure messages instead of bytes.
static void PrintTo(ConfigWatcher::Change c, std::ostream* os) {
    static constexpr const char* names[] = {"None", "Written", "Removed"};
    *os << names[static_cast<int>(c)];
}

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

// `rm -rf` of the config's folder, then `mkdir` and a new file: reloads, and later edits too.
TEST(ConfigWatcher, AFolderRemovedAndMadeAgainIsWatchedAgain) {
    test::TempDir dir;
    const auto folder = dir / "cf";
    std::filesystem::create_directories(folder);
    const auto path = folder / "p.toml";
    write_file(path, "[rain]\ndrop_count = 30\n");
    auto w = ConfigWatcher::watch(path.string());
    ASSERT_TRUE(w) << w.error().message;
    std::filesystem::remove_all(folder);
    EXPECT_EQ(w->poll(), Change::Removed);
    std::filesystem::create_directory(folder);
    EXPECT_EQ(w->poll(), Change::None) << "the folder is back, the file is not: nothing to say again";
    write_file(path, "[rain]\ndrop_count = 34\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the file came back in the new folder";
    write_file(path, "[rain]\ndrop_count = 35\n");
    EXPECT_EQ(w->poll(), Change::Written) << "and later edits are followed";
    // All of it between two polls (the folder and the file made before the watcher looks).
    std::filesystem::remove_all(folder);
    std::filesystem::create_directory(folder);
    write_file(path, "[rain]\ndrop_count = 36\n");
    EXPECT_EQ(w->poll(), Change::Written);
    write_file(path, "[rain]\ndrop_count = 37\n");
    EXPECT_EQ(w->poll(), Change::Written);
}

TEST(ConfigWatcher, ALinkedConfigsTargetFolderRemovedAndMadeAgainIsWatchedAgain) {
    LinkedConfig c;
    auto w = ConfigWatcher::watch(c.link.string());
    ASSERT_TRUE(w) << w.error().message;
    std::filesystem::remove_all(c.opt);
    EXPECT_EQ(w->poll(), Change::Removed);
    std::filesystem::create_directory(c.opt);
    EXPECT_EQ(w->poll(), Change::None);
    write_file(c.target, "[rain]\ndrop_count = 35\n");
    EXPECT_EQ(w->poll(), Change::Written) << "the target came back";
    write_file(c.target, "[rain]\ndrop_count = 36\n");
    EXPECT_EQ(w->poll(), Change::Written) << "and later edits are followed";
}

// A release swapped in by renames (`mv app app.old; mv app.new app`): the config's folder is renamed away.
TEST(ConfigWatcher, AFolderSwappedByRenamesIsFollowed) {
    test::TempDir dir;
    std::filesystem::create_directories(dir / "app/etc");
    std::filesystem::create_directories(dir / "app.new/etc");
    const auto path = dir / "app/etc/puddle.toml";
    write_file(path, "[rain]\ndrop_count = 1\n");
    write_file(dir / "app.new/etc/puddle.toml", "[rain]\ndrop_count = 2\n");
    auto w = ConfigWatcher::watch(path.string());
    ASSERT_TRUE(w) << w.error().message;
    std::filesystem::rename(dir / "app", dir / "app.old");
    EXPECT_EQ(w->poll(), Change::Removed);
    std::filesystem::rename(dir / "app.new", dir / "app");
    EXPECT_EQ(w->poll(), Change::Written) << "the new release's config";
    write_file(path, "[rain]\ndrop_count = 3\n");
    EXPECT_EQ(w->poll(), Change::Written);
    write_file(dir / "app.old/etc/puddle.toml", "[rain]\ndrop_count = 4\n");
    EXPECT_EQ(w->poll(), Change::None) << "the old release is no longer the config";
}

// The usual release layout: etc/puddle.toml -> ../rel/current/puddle.toml, rel/current -> v1, flipped.
TEST(ConfigWatcher, FollowsALinkedFolderInTheChainWhenItIsFlipped) {
    test::TempDir dir;
    const auto rel = dir / "rel";
    std::filesystem::create_directories(rel / "v1");
    std::filesystem::create_directories(rel / "v2");
    std::filesystem::create_directories(dir / "etc");
    write_file(rel / "v1/puddle.toml", "[rain]\ndrop_count = 10\n");
    write_file(rel / "v2/puddle.toml", "[rain]\ndrop_count = 20\n");
    std::filesystem::create_directory_symlink("v1", rel / "current");
    std::filesystem::create_symlink("../rel/current/puddle.toml", dir / "etc/puddle.toml");
    auto w = ConfigWatcher::watch((dir / "etc/puddle.toml").string());
    ASSERT_TRUE(w) << w.error().message;
    repoint(rel / "current", "v2");
    EXPECT_EQ(w->poll(), Change::Written) << "rel/current now leads to v2";
    write_file(rel / "v2/puddle.toml", "[rain]\ndrop_count = 21\n");
    EXPECT_EQ(w->poll(), Change::Written) << "edits of the new real target are seen";
    write_file(rel / "v1/puddle.toml", "[rain]\ndrop_count = 11\n");
    EXPECT_EQ(w->poll(), Change::None) << "the old one is no longer the config";

    // Flipped back atomically, as deploy tools do.
    repoint(rel / "current.new", "v1");
    EXPECT_EQ(w->poll(), Change::None) << "a new link beside it is not the config yet";
    const std::string mv =
        "mv -T '" + (rel / "current.new").string() + "' '" + (rel / "current").string() + "'";
    ASSERT_EQ(std::system(mv.c_str()), 0) << mv;
    EXPECT_EQ(w->poll(), Change::Written) << "rel/current leads to v1 again";
    write_file(rel / "v1/puddle.toml", "[rain]\ndrop_count = 12\n");
    EXPECT_EQ(w->poll(), Change::Written);
    write_file(rel / "v2/puddle.toml", "[rain]\ndrop_count = 22\n");
    EXPECT_EQ(w->poll(), Change::None);

    const auto chain = w->chain();
    ASSERT_EQ(chain.size(), 3u) << "the config's link, the folder's link and the file";
    EXPECT_EQ(chain[1].folder, rel.string());
    EXPECT_EQ(chain[1].name, "current");
    EXPECT_EQ(chain[2].folder, (rel / "v1").string());
}

// A FIFO or a folder in the config's place is reported, so that the reload says what it is (and keeps the
// last good configuration) instead of saying nothing.
TEST(ConfigWatcher, SomethingThatIsNotAFileInTheConfigsPlaceIsReported) {
    test::TempDir dir;
    const std::string path = dir.write("puddle.toml", "[rain]\n");
    auto w = ConfigWatcher::watch(path);
    ASSERT_TRUE(w) << w.error().message;
    std::filesystem::remove(path);
    EXPECT_EQ(w->poll(), Change::Removed);
    ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
    EXPECT_EQ(w->poll(), Change::Written);
    auto fifo = load_config_file(path);
    ASSERT_FALSE(fifo);
    EXPECT_EQ(fifo.error().message, "config: " + path + ": is a FIFO, not a file");

    std::filesystem::remove(path);
    EXPECT_EQ(w->poll(), Change::Removed);
    std::filesystem::create_directory(path);
    EXPECT_EQ(w->poll(), Change::Written);
    auto folder = load_config_file(path);
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error().message, "config: " + path + ": is a folder, not a file");

    std::filesystem::remove(path);
    EXPECT_EQ(w->poll(), Change::Removed);
    write_file(path, "[rain]\ndrop_count = 3\n");
    EXPECT_EQ(w->poll(), Change::Written) << "a file again";
}

TEST(ConfigWatcher, AMissingFolderIsAnErrorNamingIt) {
    auto w = ConfigWatcher::watch("/nonexistent-puddle-dir/puddle.toml");
    ASSERT_FALSE(w);
    EXPECT_NE(w.error().message.find("/nonexistent-puddle-dir"), std::string::npos) << w.error().message;
}

}  // namespace
}  // namespace puddle::params
