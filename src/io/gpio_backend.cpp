#include "io/gpio_backend.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "io/gpio_mock.hpp"

namespace puddle::io {

bool is_number(std::string_view text) {
    // At most 9 digits, so std::stoi on it cannot throw: "99999999999" in a mock script is no command.
    if (text.empty() || text.size() > 9) return false;
    for (char c : text)
        if (c < '0' || c > '9') return false;
    return true;
}

std::vector<std::string> gpio_chip_paths() {
    std::vector<std::string> paths;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/dev", ec))
        if (e.path().filename().string().starts_with("gpiochip")) paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

Error gpio_request_error(const LineRequest& r, int err) {
    const std::string where = fmt::format("gpio: {} line {}", r.chip, r.line);
    switch (err) {
        case ENOENT:
        case ENODEV:
            return make_error(ExitCode::Runtime,
                              "{}: no such chip or line (list them with gpiodetect and gpioinfo)", where);
        case EACCES:
        case EPERM:
            return make_error(
                ExitCode::Runtime,
                "{}: permission denied: add the user to group gpio (sudo usermod -aG gpio $USER) and "
                "install deploy/99-puddle-gpio.rules",
                where);
        case EBUSY:
            return make_error(ExitCode::Runtime,
                              "{}: busy: another program holds it (gpioinfo shows the consumer)", where);
        case EINVAL:
            return make_error(ExitCode::Runtime,
                              "{}: the driver refused the settings (bias or edge detection): {}", where,
                              std::strerror(err));
        default:
            return make_error(ExitCode::Runtime, "{}: {}", where, std::strerror(err));
    }
}

Result<void> check_gpio_spec(std::string_view spec) {
    if (spec.empty() || spec == "gpiod" || spec.starts_with("mock:")) return {};  // "mock:": no script
    return make_error(ExitCode::Config,
                      "--gpio {}: expected \"gpiod\" or \"mock:PATH\" (a script or FIFO of line changes)",
                      spec);
}

Result<std::unique_ptr<GpioBackend>> make_gpio_backend(std::string_view spec) {
    if (auto r = check_gpio_spec(spec); !r) return r.error();
    if (spec.starts_with("mock:")) {
        std::unique_ptr<GpioBackend> mock = std::make_unique<MockGpio>(std::string(spec.substr(5)));
        return mock;
    }
    return make_gpiod_backend();
}

}  // namespace puddle::io
