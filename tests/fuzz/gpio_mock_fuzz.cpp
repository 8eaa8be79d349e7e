// Fuzz target: the GPIO mock's script (`--gpio mock:PATH`), read from a file as the running program reads
// it: knob lines requested first, then polled at later and later times so `wait` lines take effect. Any
// text gives commands or "not a command" warnings; edges come back in time order on the lines asked for.

#include <array>
#include <memory>
#include <vector>

#include "fuzz_support.hpp"
#include "io/gpio_mock.hpp"

using namespace puddle;
using namespace puddle::io;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::write_scratch_file("gpio-script", {data, size});
    MockGpio gpio(path);
    std::vector<std::unique_ptr<GpioLine>> lines;
    for (const char* line : {"17", "18", "GPIO27"}) {
        auto requested = gpio.request(LineRequest{.chip = "gpiochip0", .line = line});
        if (requested) lines.push_back(std::move(requested).value());
    }
    PUDDLE_FUZZ_CHECK(lines.size() == 3, "the start-up chip refused a free line");
    std::array<LineEvent, 16> events;
    for (int step = 0; step < 16; ++step) {
        const double now = step * 0.25;
        gpio.poll(now);
        for (auto& line : lines) {
            auto n = line->read_events(events);
            if (!n) continue;  // the chip was removed: the line is gone, as on real hardware
            PUDDLE_FUZZ_CHECK(*n <= events.size(), "read_events returned %zu events", *n);
            for (std::size_t i = 1; i < *n; ++i)
                PUDDLE_FUZZ_CHECK(events[i - 1].time <= events[i].time, "edges out of order");
            (void)line->level();
        }
    }
    // A chip added by the script takes requests like the first one.
    for (const GpioChipInfo& chip : gpio.chips())
        (void)gpio.request(LineRequest{.chip = chip.name, .line = "1"});
    return 0;
}
