// Tests for src/camera/v4l2_io.hpp: xioctl retries only EINTR and keeps any other errno; which errors
// mean the device is gone; a DeviceFd closes and a Mapping unmaps through the seam, once.
#include "camera/v4l2_io.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <vector>

namespace puddle::camera {
namespace {

// A seam that records the calls made through it; ioctl fails with each errno of `ioctl_errors` in turn,
// then succeeds.
class RecordingIo final : public V4l2Io {
public:
    std::vector<int> ioctl_errors;
    int ioctl_calls = 0;
    std::vector<int> closed;
    std::vector<std::pair<void*, std::size_t>> unmapped;

    int open(const char*, int) override { return -1; }
    int close(int fd) override {
        closed.push_back(fd);
        return 0;
    }
    int ioctl(int, unsigned long, void*) override {
        const std::size_t call = static_cast<std::size_t>(ioctl_calls++);
        if (call < ioctl_errors.size()) {
            errno = ioctl_errors[call];
            return -1;
        }
        return 0;
    }
    void* mmap(std::size_t, int, int, int, off_t) override { return nullptr; }
    int munmap(void* address, std::size_t length) override {
        unmapped.emplace_back(address, length);
        return 0;
    }
    int poll(pollfd*, nfds_t, int) override { return 0; }
};

TEST(Xioctl, RetriesWhileASignalInterruptsIt) {
    RecordingIo io;
    io.ioctl_errors = {EINTR, EINTR, EINTR};
    EXPECT_EQ(xioctl(io, 3, 0, nullptr), 0);
    EXPECT_EQ(io.ioctl_calls, 4) << "three interrupted calls, then the one that went through";
}

TEST(Xioctl, AnyOtherErrorIsReturnedAtOnceWithItsErrno) {
    for (int err : {EIO, EAGAIN, ENODEV, EINVAL}) {
        RecordingIo io;
        io.ioctl_errors = {EINTR, err, EINTR};
        errno = 0;
        EXPECT_EQ(xioctl(io, 3, 0, nullptr), -1);
        EXPECT_EQ(errno, err);
        EXPECT_EQ(io.ioctl_calls, 2) << "the interrupted call retried, the failed one not";
    }
}

TEST(DeviceVanished, OnlyEnodevAndEnxioMeanTheDeviceIsGone) {
    EXPECT_TRUE(device_vanished(ENODEV)) << "unplugged";
    EXPECT_TRUE(device_vanished(ENXIO)) << "driver unbound";
    for (int err : {0, EIO, EPIPE, ENOMEM, EINVAL, EAGAIN, EINTR, EBUSY, ENOENT})
        EXPECT_FALSE(device_vanished(err)) << err;
}

TEST(DeviceFd, ClosesThroughTheSeamOnce) {
    RecordingIo io;
    {
        DeviceFd fd(7, {&io});
        DeviceFd moved = std::move(fd);
        EXPECT_TRUE(io.closed.empty());
    }
    EXPECT_EQ(io.closed, std::vector<int>{7}) << "the moved-from holds nothing to close";
}

TEST(Mapping, UnmapsThroughTheSeamOnceWithItsLength) {
    RecordingIo io;
    int first = 0, second = 0;
    {
        Mapping a(io, &first, 4096);
        Mapping b = std::move(a);
        EXPECT_EQ(a.data(), nullptr);  // NOLINT(bugprone-use-after-move): what a move leaves
        EXPECT_EQ(b.size(), 4096u);
        b = Mapping(io, &second, 8192);  // the old mapping goes first
        ASSERT_EQ(io.unmapped.size(), 1u);
        EXPECT_EQ(io.unmapped[0], std::make_pair(static_cast<void*>(&first), std::size_t{4096}));
    }
    ASSERT_EQ(io.unmapped.size(), 2u);
    EXPECT_EQ(io.unmapped[1], std::make_pair(static_cast<void*>(&second), std::size_t{8192}));
}

}  // namespace
}  // namespace puddle::camera
