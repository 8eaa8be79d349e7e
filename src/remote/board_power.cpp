#include "remote/board_power.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace puddle::remote {

namespace {

constexpr std::uint32_t undervoltage_bits = (1u << 0) | (1u << 16);
constexpr std::uint32_t throttling_bits = (0x7u << 1) | (0x7u << 17);  // capped, throttled, soft limit

// A sysfs attribute's text into `out` (at most its size); false when it cannot be read.
bool read_small_file(const std::string& path, std::array<char, 32>& out, std::size_t& length) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const ssize_t n = ::read(fd, out.data(), out.size());
    ::close(fd);
    if (n <= 0) return false;
    length = static_cast<std::size_t>(n);
    return true;
}

std::optional<std::uint32_t> read_number(const std::string& path, int base) {
    std::array<char, 32> text{};
    std::size_t length = 0;
    if (path.empty() || !read_small_file(path, text, length)) return std::nullopt;
    const char* begin = text.data();
    const char* end = text.data() + length;
    if (base == 16 && end - begin > 2 && begin[0] == '0' && (begin[1] == 'x' || begin[1] == 'X')) begin += 2;
    std::uint32_t value = 0;
    const auto [ptr, ec] = std::from_chars(begin, end, value, base);
    if (ec != std::errc() || ptr == begin) return std::nullopt;
    return value;
}

}  // namespace

BoardPower decode_throttled(std::uint32_t flags) {
    return {.undervoltage = (flags & undervoltage_bits) != 0, .throttled = (flags & throttling_bits) != 0};
}

BoardPowerWatch::BoardPowerWatch(const BoardPowerPaths& paths) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(paths.hwmon_dir, ec)) {
        std::ifstream name_file(entry.path() / "name");
        std::string name;
        if (!(name_file >> name) || name != "rpi_volt") continue;
        const auto alarm = entry.path() / "in0_lcrit_alarm";
        if (std::filesystem::exists(alarm, ec)) alarm_file_ = alarm.string();
        break;
    }
    if (read_number(paths.throttled_file, 16)) {
        throttled_file_ = paths.throttled_file;
        has_throttled_ = true;
    }
}

void BoardPowerWatch::poll() {
    if (const auto alarm = read_number(alarm_file_, 10); alarm && *alarm != 0) undervoltage_ = true;
    if (auto flags = read_number(throttled_file_, 16)) {
        // The "has occurred" bits are recent only where the hwmon driver clears them (every 2 s); without
        // it they hold since boot, and only the bits for now count (polled once a second).
        if (alarm_file_.empty()) *flags &= 0xfu;
        const BoardPower seen = decode_throttled(*flags);
        undervoltage_ = undervoltage_ || *seen.undervoltage;
        throttled_ = throttled_ || *seen.throttled;
    }
}

BoardPower BoardPowerWatch::take() {
    BoardPower out;
    if (present()) out.undervoltage = undervoltage_;
    if (has_throttled_) out.throttled = throttled_;
    undervoltage_ = throttled_ = false;
    return out;
}

}  // namespace puddle::remote
