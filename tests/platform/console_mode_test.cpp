// ConsoleGraphicsMode against a fake virtual terminal behind the ConsoleIo seam: the terminal is put in
// graphics mode and back in the mode it was in (once, also after a move), a descriptor that is not a
// virtual terminal is left alone, and a refused switch or restore is a warning naming the terminal and
// the call.
#include "platform/console_mode.hpp"

#include <gtest/gtest.h>
#include <linux/kd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "support/log_lines.hpp"

namespace puddle::platform {
namespace {

// A virtual terminal as console_ioctl(2) documents KDGETMODE and KDSETMODE; or not a terminal at all.
class FakeConsole final : public ConsoleIo {
public:
    bool is_terminal = true;
    int mode = KD_TEXT;
    int refuse_set = 0;  // errno for KDSETMODE, 0: accepted
    std::string path = "/dev/tty1";
    std::vector<std::pair<int, int>> sets;  // (fd, mode) of each KDSETMODE

    int get_mode(int, int& out) override {
        if (!is_terminal) {
            errno = ENOTTY;
            return -1;
        }
        out = mode;
        return 0;
    }
    int set_mode(int fd, int to) override {
        sets.emplace_back(fd, to);
        if (refuse_set != 0) {
            errno = refuse_set;
            return -1;
        }
        mode = to;
        return 0;
    }
    std::string name(int) override { return is_terminal ? path : std::string(); }
};

TEST(ConsoleMode, GraphicsWhileHeldThenTheModeItWasIn) {
    FakeConsole tty;
    {
        auto held = ConsoleGraphicsMode::enter(tty, 5);
        ASSERT_TRUE(held.has_value());
        EXPECT_EQ(tty.mode, KD_GRAPHICS);
        EXPECT_EQ(tty.sets, (std::vector<std::pair<int, int>>{{5, KD_GRAPHICS}})) << "on the fd given";
    }
    EXPECT_EQ(tty.mode, KD_TEXT);
    EXPECT_EQ(tty.sets.size(), 2u) << "restored once";
}

// A console left in graphics mode by a crashed predecessor is left in graphics mode, not forced to text.
TEST(ConsoleMode, RestoresWhateverModeItFound) {
    FakeConsole tty;
    tty.mode = KD_GRAPHICS;
    ConsoleGraphicsMode::enter(tty, 0).reset();
    EXPECT_EQ(tty.sets, (std::vector<std::pair<int, int>>{{0, KD_GRAPHICS}, {0, KD_GRAPHICS}}));
}

TEST(ConsoleMode, AMovedHolderRestoresOnceWhenTheLastOwnerGoes) {
    FakeConsole tty;
    {
        auto held = ConsoleGraphicsMode::enter(tty, 0);
        ASSERT_TRUE(held.has_value());
        std::optional<ConsoleGraphicsMode> moved(std::move(*held));
        held.reset();
        EXPECT_EQ(tty.mode, KD_GRAPHICS) << "the moved-from holder restores nothing";
        EXPECT_EQ(tty.sets.size(), 1u);
    }
    EXPECT_EQ(tty.mode, KD_TEXT);
    EXPECT_EQ(tty.sets.size(), 2u);
}

TEST(ConsoleMode, ADescriptorThatIsNotAVirtualTerminalIsLeftAlone) {
    FakeConsole pipe;
    pipe.is_terminal = false;
    test::LogLines warnings(spdlog::level::warn);
    EXPECT_FALSE(ConsoleGraphicsMode::enter(pipe, 0).has_value());
    EXPECT_TRUE(pipe.sets.empty()) << "no KDSETMODE on something that is not a console";
    EXPECT_EQ(warnings.count("console"), 0) << "ssh, a pipe or a test is no fault";
}

// The kernel's side of the seam: KDGETMODE on a pipe fails (ENOTTY), so nothing is switched.
TEST(ConsoleMode, ThroughTheKernelAPipeIsNoVirtualTerminal) {
    int ends[2];
    ASSERT_EQ(::pipe(ends), 0);
    int mode = -1;
    errno = 0;
    EXPECT_EQ(system_console_io().get_mode(ends[0], mode), -1);
#ifdef PUDDLE_TESTS_UNDER_EMULATOR
    // qemu-user answers the ioctls it does not emulate, KDGETMODE among them, with ENOSYS.
    EXPECT_TRUE(errno == ENOTTY || errno == ENOSYS) << std::strerror(errno);
#else
    EXPECT_EQ(errno, ENOTTY);
#endif
    EXPECT_EQ(system_console_io().name(ends[0]), "");
    EXPECT_FALSE(ConsoleGraphicsMode::enter(system_console_io(), ends[0]).has_value());
    ::close(ends[0]);
    ::close(ends[1]);
}

TEST(ConsoleMode, ARefusedSwitchIsAWarningNamingTheTerminalAndTheCall) {
    FakeConsole tty;
    tty.path = "/dev/tty3";
    tty.refuse_set = EPERM;
    test::LogLines warnings(spdlog::level::warn);
    EXPECT_FALSE(ConsoleGraphicsMode::enter(tty, 0).has_value());
    EXPECT_EQ(
        warnings.count("console: /dev/tty3: KDSETMODE KD_GRAPHICS: Operation not permitted (console text "
                       "may show through)"),
        1);
    EXPECT_EQ(tty.sets.size(), 1u) << "nothing to restore";
}

TEST(ConsoleMode, ARefusedRestoreIsAWarningNamingTheTerminalAndTheMode) {
    FakeConsole tty;
    test::LogLines warnings(spdlog::level::warn);
    {
        auto held = ConsoleGraphicsMode::enter(tty, 0);
        ASSERT_TRUE(held.has_value());
        tty.refuse_set = EIO;
    }
    EXPECT_EQ(warnings.count("console: /dev/tty1: KDSETMODE KD_TEXT (restoring): Input/output error"), 1);
}

}  // namespace
}  // namespace puddle::platform
