#pragma once
// A GPIO backend with no hardware: chips and lines in memory, driven in-process by tests or from
// outside the process through a script file or FIFO (`puddle --gpio mock:PATH`). Each line of the
// script is one command, read as it arrives (a file is followed like `tail -f`):
//
//   gpiochip0 17 0        set the raw level of line 17 on gpiochip0 (0 or 1)
//   remove gpiochip0      unplug the chip: its lines fail, requests fail with "no such chip"
//   add gpiochip1 LABEL   plug a chip in (64 lines; LABEL optional)
//   busy gpiochip0 17     another program holds the line
//   deny gpiochip0 17     permission denied on the line
//   wait 0.5              run the rest of the script half a second later (0 to 86400 s)
//   # ...                 a comment
//
// A line longer than 4 KiB is skipped with a warning, and at most 64 KiB of the script is read ahead.
// A line that is no command is logged with its control bytes shown as '?': the first 3 as warnings,
// the rest at debug level (a binary file is not a flood of warnings).
//
// There is a chip gpiochip0 (label "mock-gpio") from the start. Line names are GPIO<offset>. A line
// nobody drove sits at its bias: high with pull-up, else low.

#include <map>
#include <memory>
#include <string>

#include "io/gpio_backend.hpp"
#include "util/unique_fd.hpp"

namespace puddle::io {

class MockGpio : public GpioBackend {
public:
    explicit MockGpio(std::string script = {});
    ~MockGpio() override;
    std::string_view name() const override { return "mock"; }
    Result<std::unique_ptr<GpioLine>> request(const LineRequest& request) override;
    void poll(double now) override;
    std::vector<GpioChipInfo> chips() override;

    // In-process control, the same as the script commands.
    void add_chip(const std::string& name, const std::string& label = {});
    void remove_chip(const std::string& name);
    void set_level(const std::string& chip, int offset, bool raw_level, double time);
    void set_error(const std::string& chip, int offset, int err);  // EBUSY, EACCES; 0 clears
    // Runs one script line; returns false (and changes nothing) when it is not a command.
    bool command(std::string_view line, double now);

    struct Chip;

private:
    void note_bad_line(std::string_view line, std::string_view why);

    std::map<std::string, std::shared_ptr<Chip>> chips_;
    std::string script_;
    UniqueFd fd_;          // the script; none without one
    std::string pending_;  // script text read but not yet run
    bool skipping_long_line_ = false;
    int bad_lines_ = 0;
    double last_time_ = 0;
    double resume_at_ = 0;  // after a `wait`
};

}  // namespace puddle::io
