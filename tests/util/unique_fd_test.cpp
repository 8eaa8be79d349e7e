// UniqueFd: the descriptor it holds is closed exactly once (destruction, reset, move-assignment), a
// move leaves the source holding none, and release() hands the descriptor over without closing it.
// Whether a descriptor is still open is asked of the kernel: fcntl(F_GETFD) fails with EBADF once closed.
#include "util/unique_fd.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>
#include <vector>

namespace puddle {
namespace {

bool is_closed(int fd) {
    errno = 0;
    return ::fcntl(fd, F_GETFD) == -1 && errno == EBADF;
}

int open_null() {
    const int fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    EXPECT_GE(fd, 0) << "/dev/null cannot be opened";
    return fd;
}

// A seam like camera::V4l2Io: records every descriptor it is asked to close, then closes it.
struct CountingIo {
    std::vector<int> closed;
    int close(int fd) {
        closed.push_back(fd);
        return ::close(fd);
    }
};
using CountedFd = BasicUniqueFd<CloseThrough<CountingIo>>;

TEST(UniqueFd, ClosesItsDescriptorWhenDestroyed) {
    const int fd = open_null();
    {
        const UniqueFd owner(fd);
        EXPECT_EQ(owner.get(), fd);
        EXPECT_TRUE(owner);
        EXPECT_FALSE(is_closed(fd));
    }
    EXPECT_TRUE(is_closed(fd));
}

TEST(UniqueFd, ClosesExactlyOnceThroughItsCloser) {
    CountingIo io;
    const int fd = open_null();
    { const CountedFd owner(fd, {&io}); }
    EXPECT_EQ(io.closed, std::vector<int>{fd});
    EXPECT_TRUE(is_closed(fd));
}

TEST(UniqueFd, HoldingNoneClosesNothing) {
    CountingIo io;
    {
        const CountedFd empty;
        EXPECT_EQ(empty.get(), -1);
        EXPECT_FALSE(empty);
        const CountedFd failed_open(-1, {&io});
        EXPECT_FALSE(failed_open);
    }
    EXPECT_TRUE(io.closed.empty());
}

TEST(UniqueFd, AMoveLeavesTheSourceEmptyAndTheDescriptorOpenUntilTheTargetDies) {
    CountingIo io;
    const int fd = open_null();
    {
        CountedFd source(fd, {&io});
        CountedFd target(std::move(source));
        EXPECT_EQ(source.get(), -1);  // NOLINT(bugprone-use-after-move): the moved-from state is the point
        EXPECT_FALSE(source);
        EXPECT_EQ(target.get(), fd);
        {
            const CountedFd moved_again(std::move(target));
            EXPECT_EQ(target.get(), -1);  // NOLINT(bugprone-use-after-move)
        }
        EXPECT_EQ(io.closed, std::vector<int>{fd});
        EXPECT_TRUE(is_closed(fd));
    }
    EXPECT_EQ(io.closed, std::vector<int>{fd});  // the emptied owners closed nothing
}

TEST(UniqueFd, MoveAssignmentClosesTheDescriptorItReplaces) {
    CountingIo io;
    const int first = open_null();
    const int second = open_null();
    CountedFd target(first, {&io});
    CountedFd source(second, {&io});
    target = std::move(source);
    EXPECT_EQ(io.closed, std::vector<int>{first});
    EXPECT_TRUE(is_closed(first));
    EXPECT_EQ(target.get(), second);
    EXPECT_EQ(source.get(), -1);  // NOLINT(bugprone-use-after-move)
    EXPECT_FALSE(is_closed(second));
}

TEST(UniqueFd, ReleaseGivesUpOwnershipWithoutClosing) {
    const int fd = open_null();
    int released = -1;
    {
        UniqueFd owner(fd);
        released = owner.release();
        EXPECT_EQ(owner.get(), -1);
        EXPECT_FALSE(owner);
    }
    EXPECT_EQ(released, fd);
    EXPECT_FALSE(is_closed(fd));
    ::close(fd);
}

TEST(UniqueFd, ResetClosesTheOldDescriptorAndOwnsTheNewOne) {
    CountingIo io;
    const int first = open_null();
    const int second = open_null();
    {
        CountedFd owner(first, {&io});
        owner.reset(second);
        EXPECT_EQ(io.closed, std::vector<int>{first});
        EXPECT_TRUE(is_closed(first));
        EXPECT_EQ(owner.get(), second);
        EXPECT_FALSE(is_closed(second));
        owner.reset();
        EXPECT_EQ(io.closed, (std::vector<int>{first, second}));
        EXPECT_TRUE(is_closed(second));
        EXPECT_FALSE(owner);
    }
    EXPECT_EQ(io.closed.size(), 2u);  // nothing closed a second time
}

}  // namespace
}  // namespace puddle
