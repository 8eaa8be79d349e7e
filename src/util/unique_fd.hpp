#pragma once
// The one owner of a POSIX file descriptor: move-only, closes the descriptor it holds exactly once (on
// destruction, reset() or move-assignment), and -1 means "holds none". A closer that fails with EINTR is
// not retried: Linux has freed the descriptor by then, and a second close(2) could close a descriptor
// another thread has just been given (close(2), "Dealing with error returns from close()").
//
// UniqueFd closes with close(2). A descriptor opened through a test seam (camera::V4l2Io, platform::CecIo)
// must be closed through the same seam, so the fake devices see (and count) every close:
// BasicUniqueFd<CloseThrough<Io>> calls io->close(fd) instead.

#include <unistd.h>

#include <utility>

namespace puddle {

// close(2); its result is ignored (see above: EINTR must not be retried, and nothing else can be done).
struct PosixClose {
    void operator()(int fd) const noexcept { static_cast<void>(::close(fd)); }
};

// Closes through a seam object with `int close(int fd)`; it must outlive every descriptor it closes.
template <class Io>
struct CloseThrough {
    Io* io = nullptr;
    void operator()(int fd) const { static_cast<void>(io->close(fd)); }
};

template <class Closer>
class BasicUniqueFd {
public:
    BasicUniqueFd() = default;
    // Takes ownership of `fd` (a negative value: holds none).
    explicit BasicUniqueFd(int fd, Closer closer = Closer{}) noexcept : fd_(fd), closer_(std::move(closer)) {}
    BasicUniqueFd(BasicUniqueFd&& other) noexcept
        : fd_(std::exchange(other.fd_, -1)), closer_(std::move(other.closer_)) {}
    BasicUniqueFd& operator=(BasicUniqueFd&& other) noexcept {
        if (this != &other) {
            reset();
            fd_ = std::exchange(other.fd_, -1);
            closer_ = std::move(other.closer_);
        }
        return *this;
    }
    BasicUniqueFd(const BasicUniqueFd&) = delete;
    BasicUniqueFd& operator=(const BasicUniqueFd&) = delete;
    ~BasicUniqueFd() { reset(); }

    // The descriptor, still owned; -1 when none.
    int get() const noexcept { return fd_; }
    explicit operator bool() const noexcept { return fd_ >= 0; }

    // Gives the descriptor up without closing it; the caller now owns it. -1 when none was held.
    [[nodiscard]] int release() noexcept { return std::exchange(fd_, -1); }

    // Closes the descriptor held (if any), then owns `fd` (by default none). The closer stays.
    void reset(int fd = -1) noexcept {
        if (const int old = std::exchange(fd_, fd); old >= 0) closer_(old);
    }

private:
    int fd_ = -1;
    [[no_unique_address]] Closer closer_{};
};

using UniqueFd = BasicUniqueFd<PosixClose>;

}  // namespace puddle
