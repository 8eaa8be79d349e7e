#pragma once
// The seam between Puddle and GPIO: request a line, read its level, read its edges without blocking.
// One implementation per file: libgpiod 1.6 (Debian 12), libgpiod 2 (where pkg-config finds it), and a
// mock driven from a script or FIFO so the real binary can be tested with no hardware.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "params/knob_spec.hpp"
#include "util/result.hpp"

namespace puddle::io {

// An edge: the line's logical level after it (active-low already applied) and when it happened, in
// CLOCK_MONOTONIC seconds (the kernel's event timestamps use that clock).
struct LineEvent {
    bool level = false;
    double time = 0;
};

struct LineRequest {
    std::string chip;  // "gpiochip0", "/dev/gpiochip0", a label ("pinctrl-bcm2711") or a number ("0")
    std::string line;  // an offset ("17") or a line name ("GPIO17")
    bool active_low = false;
    params::LineBias bias = params::LineBias::AsIs;
};

class GpioLine {
public:
    virtual ~GpioLine() = default;
    // The logical level now.
    virtual Result<bool> level() = 0;
    // Fills `out` with edges that arrived since the last call, oldest first; never blocks. An error
    // means the line is gone (the chip was unplugged): close it and request it again later.
    virtual Result<std::size_t> read_events(std::span<LineEvent> out) = 0;
};

// A GPIO chip as `puddle --check` lists it.
struct GpioChipInfo {
    std::string name;   // gpiochip0
    std::string label;  // pinctrl-bcm2711
    unsigned lines = 0;
    std::string error;  // set when it could not be opened (permissions)
};

class GpioBackend {
public:
    virtual ~GpioBackend() = default;
    virtual std::string_view name() const = 0;
    // Requests one line for edge events. Errors name the chip, the line and the fix.
    virtual Result<std::unique_ptr<GpioLine>> request(const LineRequest& request) = 0;
    // Called once per frame before lines are read (the mock reads its script here).
    virtual void poll(double /*now*/) {}
    // The chips this backend can see.
    virtual std::vector<GpioChipInfo> chips() = 0;
};

// /dev/gpiochip* in name order (shared by the libgpiod backends).
std::vector<std::string> gpio_chip_paths();

// The libgpiod backend this build has (v1 or v2; defined in gpio_gpiod_v1.cpp or gpio_gpiod_v2.cpp).
std::unique_ptr<GpioBackend> make_gpiod_backend();
// "gpiod" (the default) or "mock:PATH" (a script or FIFO of mock line changes, see gpio_mock.hpp).
Result<std::unique_ptr<GpioBackend>> make_gpio_backend(std::string_view spec);
// Whether --gpio names a backend at all ("gpiod", "mock:PATH"); checked even when no knob needs one, so
// a typo is exit 2 at once and not only after knobs are added. Error code Config.
Result<void> check_gpio_spec(std::string_view spec);

// The one-line message for a failed request: what, where, and how to fix it.
Error gpio_request_error(const LineRequest& request, int err);
// True when every character is a digit and there are at most 9 (a line offset or chip number rather than a
// name; std::stoi on it cannot overflow).
bool is_number(std::string_view text);

}  // namespace puddle::io
