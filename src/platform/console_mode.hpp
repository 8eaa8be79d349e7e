#pragma once
// The text console under a KMS display: switched to graphics mode while Puddle owns the screen (so the
// kernel neither draws a blinking cursor nor console text over the picture) and back to the mode it was in
// on exit. The virtual terminal ioctls are KDGETMODE and KDSETMODE (linux/kd.h; console_ioctl(2)).

#include <optional>
#include <string>

namespace puddle::platform {

// The seam where the console code meets the kernel; tests give a fake terminal with the same contract
// (return -1 and set errno).
class ConsoleIo {
public:
    virtual ~ConsoleIo() = default;
    virtual int get_mode(int fd, int& mode) = 0;  // ioctl(fd, KDGETMODE, &mode)
    virtual int set_mode(int fd, int mode) = 0;   // ioctl(fd, KDSETMODE, mode)
    // The terminal's device path ("/dev/tty1", ttyname(3)), or empty when it has none.
    virtual std::string name(int fd) = 0;
};
// The kernel: ioctl(2) and ttyname_r(3).
ConsoleIo& system_console_io();

class ConsoleGraphicsMode {
public:
    // Switches the virtual terminal on `fd` (stdin: the service's TTYPath) to graphics mode, remembering
    // the mode it was in. Nothing, and no warning, when `fd` is not a virtual terminal (KDGETMODE fails:
    // ssh, a pipe, tests). Nothing when the switch is refused; the warning names the terminal, the call and
    // the reason: "console: /dev/tty1: KDSETMODE KD_GRAPHICS: Operation not permitted (...)".
    static std::optional<ConsoleGraphicsMode> enter(ConsoleIo& io = system_console_io(), int fd = 0);
    ConsoleGraphicsMode(ConsoleGraphicsMode&& other) noexcept;
    ConsoleGraphicsMode& operator=(ConsoleGraphicsMode&&) = delete;
    ConsoleGraphicsMode(const ConsoleGraphicsMode&) = delete;
    // Puts the terminal back in the mode it was in; a failure is logged as a warning naming the terminal.
    ~ConsoleGraphicsMode();

private:
    ConsoleGraphicsMode(ConsoleIo& io, int fd, std::string name, int previous)
        : io_(&io), fd_(fd), name_(std::move(name)), previous_(previous) {}
    ConsoleIo* io_;
    int fd_ = -1;  // not owned; -1 once moved from
    std::string name_;
    int previous_ = 0;
};

}  // namespace puddle::platform
