#include "platform/console_mode.hpp"

#include <linux/kd.h>
#include <spdlog/spdlog.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace puddle::platform {

std::optional<ConsoleGraphicsMode> ConsoleGraphicsMode::enter() {
    int mode = 0;
    if (ioctl(STDIN_FILENO, KDGETMODE, &mode) != 0) return std::nullopt;  // not a virtual terminal
    if (ioctl(STDIN_FILENO, KDSETMODE, KD_GRAPHICS) != 0) {
        spdlog::warn(
            "console: cannot switch the terminal to graphics mode: {} (console text may show through)",
            std::strerror(errno));
        return std::nullopt;
    }
    spdlog::info("console: graphics mode until puddle exits");
    return ConsoleGraphicsMode(STDIN_FILENO, mode);
}

ConsoleGraphicsMode::~ConsoleGraphicsMode() {
    if (fd_ >= 0) ioctl(fd_, KDSETMODE, previous_);
}

}  // namespace puddle::platform
