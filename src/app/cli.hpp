#pragma once
// The command line. Parsing is separate from running so it can be tested and so `--help` is the one
// place the flags are described.

#include <optional>
#include <string>
#include <vector>

#include "platform/display.hpp"
#include "util/result.hpp"

namespace puddle::app {

struct CliOptions {
    std::string config_path;        // empty: /etc/puddle/puddle.toml when it exists, else built-in defaults
    std::vector<std::string> sets;  // --set name=value, applied last
    std::string preset;             // --preset NAME (or --set preset=NAME): instead of the config's preset =
    bool list_params = false;
    bool markdown = false;  // --list-params as docs/parameters.md's Markdown table
    bool print_config = false;
    bool check = false;  // --check: report on this machine and exit
    platform::DisplayOptions display;
    std::optional<long> frames;  // stop after N frames (headless default: 180)
    std::string screenshot;      // write the last frame as PNG
    // --screenshot-at: with wall.clock = "realtime", the wall time (seconds since the Unix epoch) whose
    // wave step is written to `screenshot`, after which the run ends; every screen given the same time
    // writes the same step.
    std::optional<double> screenshot_at;
    std::optional<int> seed;  // shorthand for --set rain.seed=N
    double fps_cap = 0;       // 0: the display's pace (vblank), headless: as fast as possible
    bool fixed_step = false;  // every backend advances 1/60 s (or 1/fps-cap) per frame, as headless does
    // --hold-after N: from frame N+1 on, simulated time stops, so the picture of frame N stays on screen
    // while the display, reloads, knobs and the watchdog carry on (a screen checked against a headless
    // render of N frames knows what it shows). 0: off.
    long hold_after = 0;
    std::string log_level = "info";
    std::string camera;          // --camera DEVICE|mock:PATH: environment.source = camera from that device
    double stats_every = 0;      // --stats[=SECONDS]: log fps, frame-time percentiles, CPU and memory; 0: off
    std::string gpio = "gpiod";  // knob backend: gpiod, or mock:PATH (a script or FIFO of line changes)
    std::string state_path;  // knob state file; empty: $STATE_DIRECTORY, $XDG_STATE_HOME or ~/.local/state
};

// Returns the options, or an Error with exit code 2 for bad flags. `--help` and `--version` print and
// return an Error with exit code 0 (the caller exits with it).
Result<CliOptions> parse_command_line(int argc, const char* const* argv);

// The puddle(1) man page as roff (man(7) macros), made from the same option definitions as --help, with
// the examples, exit codes and files. The package installs deploy/puddle.1; a unit test keeps that file
// equal to this text (Debian policy 12.1: every program in /usr/bin has a manual page).
std::string format_man_page();

}  // namespace puddle::app
