#pragma once
// The text console under a KMS display: switched to graphics mode while Puddle owns the screen (so the
// kernel neither draws a blinking cursor nor console text over the picture) and back to text on exit.

#include <optional>

namespace puddle::platform {

class ConsoleGraphicsMode {
public:
    // Switches the virtual terminal on stdin (the service's TTYPath) to graphics mode. Nothing, and
    // no error, when stdin is not a virtual terminal (ssh, a pipe, tests).
    static std::optional<ConsoleGraphicsMode> enter();
    ConsoleGraphicsMode(ConsoleGraphicsMode&& other) noexcept : fd_(other.fd_), previous_(other.previous_) {
        other.fd_ = -1;
    }
    ConsoleGraphicsMode& operator=(ConsoleGraphicsMode&&) = delete;
    ConsoleGraphicsMode(const ConsoleGraphicsMode&) = delete;
    ~ConsoleGraphicsMode();

private:
    ConsoleGraphicsMode(int fd, int previous) : fd_(fd), previous_(previous) {}
    int fd_ = -1;
    int previous_ = 0;
};

}  // namespace puddle::platform
