// What a state save must never destroy: a file that could not be
// read and could not be set aside is never replaced; a state path that is a symbolic link is written
// through and stays a link; a failed save leaves no temporary file behind.
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>

#include "params/state_store.hpp"
#include "support/test_support.hpp"

namespace puddle::params {
namespace {

namespace fs = std::filesystem;
using test::read_file;

// Every name under `dir`, relative, links not followed.
std::set<std::string> names_under(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        names.insert(e.path().lexically_relative(dir).string());
    return names;
}

bool has_text(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Runs `body` in a child process and returns its exit code (-1 when it did not exit): for what changes
// the whole process (a file size limit, the user).
template <typename Body>
int in_child(Body body) {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(body());
    int status = 0;
    if (child < 0 || ::waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
}

const std::string new_state = "[rain]\nintensity = 0.4\n";

// Finding 1's kind, without needing permissions: a state file the loader cannot read (a FIFO; a regular
// file over 1 MiB) whose name leaves no room for a set-aside name (NAME_MAX is 255 bytes; the copy adds
// 26), so every way of keeping it fails, for root too. The saves that follow must leave it as it is.
// (Before the fix, set_aside() also waited forever on the FIFO, opening it to copy it.)
TEST(StateStoreSafety, AFileThatCouldNotBeReadNorSetAsideIsNeverReplaced) {
    test::TempDir dir;
    const std::string name = "state" + std::string(235, 's') + ".toml";  // 244 bytes with ".tmp": fits
    const std::string big(2 * 1024 * 1024, '#');
    for (const bool fifo : {false, true}) {
        SCOPED_TRACE(fifo ? "a FIFO" : "a 2 MiB file");
        const fs::path folder = dir / (fifo ? "fifo" : "big");
        fs::create_directories(folder);
        const std::string path = (folder / name).string();
        if (fifo)
            ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
        else
            dir.write("big/" + name, big);

        StateStore store(path);
        const auto loaded = store.load();
        EXPECT_FALSE(loaded.state);
        ASSERT_EQ(loaded.problems.size(), 1u);
        EXPECT_TRUE(loaded.problems[0].starts_with("state: " + path + ": ")) << loaded.problems[0];
        EXPECT_TRUE(
            loaded.problems[0].ends_with("; no saved value could be read (the config's values apply)"))
            << loaded.problems[0];

        const auto aside = store.set_aside();
        ASSERT_FALSE(aside);
        EXPECT_TRUE(aside.error().message.starts_with("state: cannot set " + path + " aside as " + path +
                                                      ".bad-0001-"))
            << aside.error().message;
        EXPECT_TRUE(aside.error().message.ends_with(
            ": File name too long; knob changes are not saved, so it stays as it is"))
            << aside.error().message;
        EXPECT_EQ(store.refusal(), aside.error().message + "; saving resumes once it is moved away");

        for (int save = 0; save < 2; ++save) {
            const auto saved = store.save(new_state);
            ASSERT_FALSE(saved) << "save " << save << " replaced a file that was never kept";
            EXPECT_EQ(saved.error().message, store.refusal());
        }
        EXPECT_EQ(names_under(folder), std::set<std::string>{name}) << "a copy or a temporary file appeared";
        if (fifo) {
            struct stat st {};
            ASSERT_EQ(::lstat(path.c_str(), &st), 0);
            EXPECT_TRUE(S_ISFIFO(st.st_mode));
        } else {
            EXPECT_EQ(read_file(path), big);
        }
        // Once someone moves the file away, saving resumes (it used to stay refused until a restart).
        const std::string moved = (folder / "moved").string();
        ASSERT_EQ(::rename(path.c_str(), moved.c_str()), 0);
        const auto resumed = store.save(new_state);
        ASSERT_TRUE(resumed) << resumed.error().message;
        EXPECT_EQ(read_file(path), new_state);
        EXPECT_EQ(store.refusal(), "");
    }
}

// A folder at the state path (`--state /var/lib/puddle`) is never moved, replaced or written beside.
TEST(StateStoreSafety, AFolderAtTheStatePathIsNeitherMovedNorReplacedAndGetsNoTemporaryFile) {
    test::TempDir dir;
    const std::string path = (dir / "state.toml").string();
    dir.write("state.toml/kept.txt", "the user's file");
    const auto before = names_under(dir.path());

    StateStore store(path);
    // A save on its own fails at the rename, and takes its temporary file away again.
    const auto saved = store.save(new_state);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().message, "state: cannot replace " + path + ": Is a directory");
    EXPECT_EQ(names_under(dir.path()), before);

    const auto aside = store.set_aside();
    ASSERT_FALSE(aside);
    EXPECT_EQ(aside.error().message,
              "state: " + path + " is a folder, not a file; knob changes are not saved");
    const auto refused = store.save(new_state);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().message, aside.error().message + "; saving resumes once it is moved away");
    EXPECT_EQ(names_under(dir.path()), before);
    EXPECT_EQ(read_file(dir / "state.toml" / "kept.txt"), "the user's file");
}

// A full disk, played by a file size limit of 8 bytes (which binds root too): the temporary file is
// removed and the old state stays.
TEST(StateStoreSafety, AWriteThatFailsLeavesNoTemporaryFileAndTheOldState) {
    test::TempDir dir;
    const std::string path = dir.write("state.toml", "[rain]\nintensity = 0.7\n");
    const int code = in_child([&] {
        ::signal(SIGXFSZ, SIG_IGN);  // write() then fails with EFBIG instead of the signal ending the child
        const rlimit limit{8, 8};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) return 10;
        const auto saved = StateStore(path).save(new_state);
        if (saved) return 11;
        return saved.error().message == "state: cannot write " + path + ".tmp: File too large" ? 0 : 12;
    });
    EXPECT_EQ(code, 0) << "10: no limit, 11: the save worked, 12: another message";
    EXPECT_EQ(names_under(dir.path()), std::set<std::string>{"state.toml"});
    EXPECT_EQ(read_file(path), "[rain]\nintensity = 0.7\n");
}

// Finding 1 as the reviewer met it: a root-owned 0600 state file (what one `sudo puddle` leaves) in a
// folder the service user owns. That user can neither read nor hard-link it (fs.protected_hardlinks), so
// it is renamed aside, which the folder allows, and only then saved over.
TEST(StateStoreSafety, AnotherUsersUnreadableFileIsRenamedAsideBeforeASave) {
    if (::geteuid() != 0)
        GTEST_SKIP() << "needs root: only root can make a state file owned by another user, which the test "
                        "then reads as user 65534 (CI runs as root)";
    test::TempDir dir;
    const fs::path folder = dir / "state";
    fs::create_directories(folder);
    ASSERT_EQ(::chown(folder.c_str(), 65534, 65534), 0);
    const std::string old_state = "[rain]\nintensity = 0.8\n[look]\nvignette = 1.2\n";
    const std::string path = dir.write("state/state.toml", old_state);
    ASSERT_EQ(::chmod(path.c_str(), 0600), 0);

    const int code = in_child([&] {
        if (::setgroups(0, nullptr) != 0 || ::setresgid(65534, 65534, 65534) != 0 ||
            ::setresuid(65534, 65534, 65534) != 0)
            return 10;
        StateStore store(path);
        const auto loaded = store.load();
        if (loaded.state || loaded.problems.size() != 1 || !has_text(loaded.problems[0], "Permission denied"))
            return 11;
        if (!store.set_aside()) return 12;
        return store.save(new_state) ? 0 : 13;
    });
    ASSERT_EQ(code, 0) << "10: cannot become user 65534, 11: the file was readable, 12: not set aside, "
                          "13: not saved";
    const auto names = names_under(folder);
    ASSERT_EQ(names.size(), 2u);
    const std::string copy = *names.rbegin();
    EXPECT_TRUE(copy.starts_with("state.toml.bad-0001-")) << copy;
    EXPECT_EQ(read_file(folder / copy), old_state);
    EXPECT_EQ(read_file(path), new_state);
}

// Finding 2: a state path that links to persistent storage (a read-only image) is written through.
TEST(StateStoreSafety, ALinkedStatePathIsWrittenThroughAndStaysALink) {
    test::TempDir dir;
    const std::string target = dir.write("data/state.toml", "[rain]\nintensity = 0.8\n");
    fs::create_directories(dir / "sd");
    const fs::path link = dir / "sd" / "state.toml";
    fs::create_symlink("../data/state.toml", link);

    StateStore store(link.string());
    ASSERT_TRUE(store.save(new_state));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fs::read_symlink(link), "../data/state.toml");
    EXPECT_EQ(read_file(target), new_state);
    EXPECT_EQ(names_under(dir.path()),
              (std::set<std::string>{"data", "data/state.toml", "sd", "sd/state.toml"}));
    const auto loaded = store.load();
    ASSERT_TRUE(loaded.state);
    EXPECT_FLOAT_EQ(std::get<float>(loaded.state->entries[0].value), 0.4f);

    // The crash half of a save puts its temporary file beside the target, where the rename is atomic.
    auto temp = store.write_temporary("[rain]\nintensity = 0.5\n");
    ASSERT_TRUE(temp);
    EXPECT_EQ(*temp, (dir / "sd" / ".." / "data" / "state.toml.tmp").string());
}

// A chain: a relative link to a link whose target is absolute, each taken from its own folder; and a loop.
TEST(StateStoreSafety, AChainOfLinksIsFollowedToTheEndAndALoopIsRefused) {
    test::TempDir dir;
    const std::string target = dir.write("data/real.toml", "[rain]\nintensity = 0.8\n");
    fs::create_directories(dir / "sd");
    fs::create_directories(dir / "mid");
    fs::create_symlink(target, dir / "mid" / "hop.toml");
    fs::create_symlink("../mid/hop.toml", dir / "sd" / "state.toml");
    ASSERT_TRUE(StateStore((dir / "sd" / "state.toml").string()).save(new_state));
    EXPECT_EQ(read_file(target), new_state);
    EXPECT_EQ(fs::read_symlink(dir / "sd" / "state.toml"), "../mid/hop.toml");
    EXPECT_EQ(fs::read_symlink(dir / "mid" / "hop.toml"), target);

    fs::create_symlink("b.toml", dir / "sd" / "a.toml");
    fs::create_symlink("a.toml", dir / "sd" / "b.toml");
    const auto before = names_under(dir.path());
    const std::string loop = (dir / "sd" / "a.toml").string();
    const auto saved = StateStore(loop).save(new_state);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().message, "state: " + loop + ": more than 40 symbolic links in a row; not saving");
    EXPECT_EQ(names_under(dir.path()), before);
}

// A link that leads nowhere yet names the file the save creates; one whose target folder is missing (the
// storage is not mounted) makes nothing there: one line, no save.
TEST(StateStoreSafety, ADanglingLinkGetsItsTargetButAMissingFolderIsNotMade) {
    test::TempDir dir;
    fs::create_directories(dir / "sd");
    fs::create_directories(dir / "data");
    fs::create_symlink("../data/state.toml", dir / "sd" / "state.toml");
    ASSERT_TRUE(StateStore((dir / "sd" / "state.toml").string()).save(new_state));
    EXPECT_EQ(read_file(dir / "data" / "state.toml"), new_state);
    EXPECT_TRUE(fs::is_symlink(dir / "sd" / "state.toml"));

    const fs::path unmounted = dir / "sd" / "other.toml";
    fs::create_symlink("../mnt/state.toml", unmounted);
    const auto saved = StateStore(unmounted.string()).save(new_state);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().message, "state: " + unmounted.string() + " links to " +
                                         (dir / "sd" / "../mnt/state.toml").string() + ", whose folder " +
                                         (dir / "sd" / "../mnt").string() +
                                         " cannot be used (No such file or directory); not saving");
    EXPECT_FALSE(fs::exists(dir / "mnt"));
    EXPECT_TRUE(fs::is_symlink(unmounted));
}

// A bad file behind a link is kept beside the file it is, not as a copy of the link (which a save would
// then change under it).
TEST(StateStoreSafety, SettingAsideThroughALinkKeepsTheTargetsBytesBesideIt) {
    test::TempDir dir;
    const std::string bad = "[rain]\nwind = 0.5\nintensity = 0.8\n";
    const std::string target = dir.write("data/state.toml", bad);
    fs::create_directories(dir / "sd");
    const fs::path link = dir / "sd" / "state.toml";
    fs::create_symlink("../data/state.toml", link);

    StateStore store(link.string());
    auto copy = store.set_aside();
    ASSERT_TRUE(copy) << copy.error().message;
    EXPECT_EQ(fs::path(*copy).parent_path(), dir / "sd" / ".." / "data");
    EXPECT_TRUE(fs::path(*copy).filename().string().starts_with("state.toml.bad-0001-")) << *copy;
    ASSERT_TRUE(store.save(new_state));
    EXPECT_EQ(read_file(*copy), bad);
    EXPECT_EQ(read_file(target), new_state);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(names_under(dir / "sd"), std::set<std::string>{"state.toml"});
}

}  // namespace
}  // namespace puddle::params
