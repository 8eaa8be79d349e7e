#pragma once
// The seam where the camera code meets the kernel: the six calls V4L2 streaming needs. Production uses
// plain syscalls (system_v4l2_io); tests use a fake device with the same contract (return -1 or
// MAP_FAILED and set errno), so the capture code runs unchanged against both.

#include <poll.h>
#include <sys/types.h>

#include <cstddef>
#include <utility>

#include "util/unique_fd.hpp"

namespace puddle::camera {

class V4l2Io {
public:
    virtual ~V4l2Io() = default;
    virtual int open(const char* path, int flags) = 0;
    virtual int close(int fd) = 0;
    virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
    virtual void* mmap(std::size_t length, int prot, int flags, int fd, off_t offset) = 0;
    virtual int munmap(void* address, std::size_t length) = 0;
    virtual int poll(pollfd* fds, nfds_t count, int timeout_ms) = 0;
};

// The kernel: open(2), close(2), ioctl(2), mmap(2), munmap(2), poll(2).
V4l2Io& system_v4l2_io();

// ioctl retried while a signal interrupts it (EINTR), as every V4L2 caller must.
int xioctl(V4l2Io& io, int fd, unsigned long request, void* arg);

// Whether an errno from a call on an open device means the device itself is gone (ENODEV: unplugged;
// ENXIO: its driver unbound). Anything else (EIO from a USB hiccup, ENOMEM, EINVAL) may pass, and is
// retried; poll(2) reports a vanished device as POLLERR or POLLHUP instead.
bool device_vanished(int err);

// A descriptor opened through the seam, closed through it when this dies: DeviceFd(fd, {&io}).
using DeviceFd = BasicUniqueFd<CloseThrough<V4l2Io>>;

// One mmap'ed buffer, unmapped through the seam when this dies.
class Mapping {
public:
    Mapping() = default;
    Mapping(V4l2Io& io, void* address, std::size_t length) : io_(&io), address_(address), length_(length) {}
    Mapping(Mapping&& o) noexcept
        : io_(o.io_), address_(std::exchange(o.address_, nullptr)), length_(std::exchange(o.length_, 0)) {}
    Mapping& operator=(Mapping&& o) noexcept {
        if (this != &o) {
            reset();
            io_ = o.io_;
            address_ = std::exchange(o.address_, nullptr);
            length_ = std::exchange(o.length_, 0);
        }
        return *this;
    }
    Mapping(const Mapping&) = delete;
    Mapping& operator=(const Mapping&) = delete;
    ~Mapping() { reset(); }
    const std::byte* data() const { return static_cast<const std::byte*>(address_); }
    std::size_t size() const { return length_; }
    void reset() {
        if (address_) io_->munmap(std::exchange(address_, nullptr), std::exchange(length_, 0));
    }

private:
    V4l2Io* io_ = nullptr;
    void* address_ = nullptr;
    std::size_t length_ = 0;
};

}  // namespace puddle::camera
