#include "platform/console_mode.hpp"

#include <fmt/format.h>
#include <linux/kd.h>
#include <spdlog/spdlog.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <utility>

namespace puddle::platform {

namespace {

class SystemConsoleIo final : public ConsoleIo {
public:
    int get_mode(int fd, int& mode) override { return ::ioctl(fd, KDGETMODE, &mode); }
    int set_mode(int fd, int mode) override { return ::ioctl(fd, KDSETMODE, mode); }
    std::string name(int fd) override {
        std::array<char, 256> path{};
        return ::ttyname_r(fd, path.data(), path.size()) == 0 ? std::string(path.data()) : std::string();
    }
};

// The mode as linux/kd.h names it.
std::string mode_name(int mode) {
    switch (mode) {
        case KD_TEXT:
            return "KD_TEXT";
        case KD_GRAPHICS:
            return "KD_GRAPHICS";
        default:
            return std::to_string(mode);
    }
}

}  // namespace

ConsoleIo& system_console_io() {
    static SystemConsoleIo io;
    return io;
}

std::optional<ConsoleGraphicsMode> ConsoleGraphicsMode::enter(ConsoleIo& io, int fd) {
    int mode = 0;
    if (io.get_mode(fd, mode) != 0) return std::nullopt;  // not a virtual terminal
    std::string name = io.name(fd);
    if (name.empty()) name = fmt::format("fd {}", fd);
    if (io.set_mode(fd, KD_GRAPHICS) != 0) {
        spdlog::warn("console: {}: KDSETMODE KD_GRAPHICS: {} (console text may show through)", name,
                     std::strerror(errno));
        return std::nullopt;
    }
    spdlog::info("console: {} in graphics mode until puddle exits", name);
    return ConsoleGraphicsMode(io, fd, std::move(name), mode);
}

ConsoleGraphicsMode::ConsoleGraphicsMode(ConsoleGraphicsMode&& other) noexcept
    : io_(other.io_),
      fd_(std::exchange(other.fd_, -1)),
      name_(std::move(other.name_)),
      previous_(other.previous_) {}

ConsoleGraphicsMode::~ConsoleGraphicsMode() {
    if (fd_ < 0) return;
    if (io_->set_mode(fd_, previous_) != 0)
        spdlog::warn("console: {}: KDSETMODE {} (restoring): {}", name_, mode_name(previous_),
                     std::strerror(errno));
}

}  // namespace puddle::platform
