#include "app/cli.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "platform/backend_select.hpp"
#include "util/version.hpp"

namespace puddle::app {

namespace {

Result<glm::ivec2> parse_size(const std::string& s) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 16 ||
        h < 16 || w > 16384 || h > 16384)
        return make_error(ExitCode::Config,
                          "--size {}: expected WIDTHxHEIGHT, e.g. 1280x720 (16 to 16384 each)", s);
    return glm::ivec2(w, h);
}

constexpr const char* kSummary =
    "Puddle: rain falling on a puddle, for signage screens.\n"
    "Renders fullscreen on a KMS display, in a desktop window, or headless to a PNG.\n"
    "Tune it with a TOML config (see config/puddle.toml) or --set; list every parameter with "
    "--list-params.";

struct Example {
    const char* command;
    const char* what;
};
constexpr Example kExamples[] = {
    {"puddle", "pick a display by itself (kms, window, else headless)"},
    {"puddle --backend headless --frames 300 --screenshot rain.png", "render 5 s of rain to a PNG"},
    {"puddle --config /etc/puddle/puddle.toml --set rain.rate=8", "the config, with a heavier rain"},
    {"puddle --config my.toml --print-config",
     "every value and where it came from (preset, config, knob...)"},
    {"puddle --preset downpour", "a look from the presets (see --print-config for its values)"},
    {"puddle --check", "what this machine has, and what to fix"},
};

constexpr const char* kLiveTuning =
    "Live tuning: an edited config file applies within a moment (or send SIGHUP); a bad edit is logged\n"
    "with file:line and the last good config keeps running. `preset = \"downpour\"` in the config picks\n"
    "a look; [[knob]] tables wire GPIO encoders, buttons and switches (see config/puddle.toml).\n";

struct ExitStatus {
    ExitCode code;
    const char* meaning;
};
constexpr ExitStatus kExitStatuses[] = {
    {ExitCode::Ok, "ok"},
    {ExitCode::Runtime, "runtime failure"},
    {ExitCode::Config, "bad config or flag"},
    {ExitCode::Asset, "missing or bad image"},
    {ExitCode::Display, "no display"},
    {ExitCode::GpuMemory, "out of GPU memory (a texture or buffer did not fit: try a smaller size)"},
};

// Every option, its value's name and its help, on `cli`: the one definition --help and the man page
// (format_man_page) are both made from. Parsed values land in `o`, `backend` and `size`.
void describe_command_line(CLI::App& cli, CliOptions& o, std::string& backend, std::string& size) {
    std::string footer = "Examples:\n";
    for (const Example& e : kExamples) footer += fmt::format("  {}\n      {}\n", e.command, e.what);
    footer += kLiveTuning;
    footer += "Exit codes:\n";
    for (const ExitStatus& e : kExitStatuses)
        footer += fmt::format("  {}  {}\n", static_cast<int>(e.code), e.meaning);
    footer += "The manual page, puddle(1), says the same; the documentation is in /usr/share/doc/puddle.";
    cli.footer(footer);
    cli.set_version_flag("--version", std::string("puddle ") + std::string(version()));
    cli.add_option("--config,-c", o.config_path,
                   "TOML config file (default: /etc/puddle/puddle.toml if present)")
        ->type_name("FILE");
    cli.add_option("--set,-s", o.sets,
                   "Set a parameter, e.g. --set rain.rate=8 (repeatable; wins over the config)")
        ->type_name("NAME=VALUE");
    cli.add_option(
           "--preset,-p", o.preset,
           "Start with this preset, a look (downpour, drizzle, mirror, murky_pond, reference, still_night; "
           "/etc/puddle/presets and presets/ beside the config add more), instead of the config's "
           "`preset =`; --set preset=NAME is the same. A knob's preset button still changes it")
        ->type_name("NAME");
    cli.add_flag("--list-params", o.list_params,
                 "Print every parameter with its type, default, range and meaning");
    cli.add_flag("--markdown", o.markdown,
                 "With --list-params: print the Markdown table of docs/parameters.md");
    cli.add_flag("--check", o.check,
                 "Check this machine (config, screens, GPU, GPIO, cameras; the schedule's active entries and "
                 "next transition): OK or what to fix, then exit");
    cli.add_flag("--print-config", o.print_config,
                 "Print every effective value and where it came from, then exit");
    // The choices and their help come from the backend table (platform/backend_select.hpp).
    std::vector<std::string> backends{"auto"};
    std::string backend_help = "Display: auto (the first of these that works here)";
    for (const platform::BackendInfo& b : platform::display_backends()) {
        backends.emplace_back(b.name);
        backend_help += fmt::format("; {}: {}", b.name, b.summary);
    }
    cli.add_option("--backend,-b", backend, backend_help)->check(CLI::IsMember(backends))->type_name("KIND");
    cli.add_option("--size", size,
                   "Render size WIDTHxHEIGHT (headless default 640x360; kms: picks that mode)")
        ->type_name("WIDTHxHEIGHT");
    cli.add_flag("--fullscreen", o.display.fullscreen, "window backend: fill the screen");
    cli.add_option("--frames,-n", o.frames,
                   "Stop after N frames (headless default: 180, then write a PNG; 0: run until stopped)")
        ->check(CLI::Range(0L, 1000000000L))
        ->type_name("N");
    cli.add_option("--screenshot", o.screenshot,
                   "Write the last frame to this file: JPEG when it ends in .jpg or .jpeg, else PNG")
        ->type_name("FILE");
    cli.add_option("--screenshot-at", o.screenshot_at,
                   "Video walls (wall.clock = \"realtime\"): write the frame of the wave step this wall time "
                   "falls in (seconds since the Unix epoch, e.g. $(date -d '+30 sec' +%s)) to --screenshot "
                   "(default puddle-wall.png), then exit. Run it on every screen with the same time to check "
                   "the wall's alignment: all write the same step")
        ->check(CLI::Range(0.0, 1e11))
        ->type_name("SECONDS");
    cli.add_option("--seed", o.seed, "Rain seed (same as --set rain.seed=N): same seed, same rain")
        ->check(CLI::Range(0, 2147483647))
        ->type_name("N");
    cli.add_option(
           "--fps-cap", o.fps_cap,
           "kms and window: render at most this many frames per second (fanless boards); "
           "headless: each frame is 1/N s of simulated time, rendered as fast as it can be (0: no cap)")
        ->check(CLI::Range(0.0, 1000.0))
        ->check(CLI::Validator(
            [](const std::string& text) {  // CLI::Range lets "nan" through: every comparison is false
                const double v = std::strtod(text.c_str(), nullptr);
                return v == v ? std::string() : std::string("not a number");
            },
            "", "a number"))
        ->type_name("FPS");
    cli.add_flag(
        "--fixed-step", o.fixed_step,
        "Advance simulated time by 1/60 s (or 1/fps-cap) per frame on any backend, as headless runs do: "
        "frame N on a screen is then the same picture as a headless render of N frames");
    cli.add_option(
           "--hold-after", o.hold_after,
           "Stop simulated time after N frames: the picture of frame N stays on screen while the display "
           "keeps presenting it, config reloads, knobs and remote control still apply and the systemd "
           "watchdog is still pinged. With --fixed-step the held picture is a headless render of N "
           "frames, so a screen can be checked against one (the VM test does). 0: off. Ignored with "
           "wall.clock = \"realtime\", where the wall's clock sets the step")
        ->check(CLI::Range(0L, 1000000000L))
        ->type_name("N");
    cli.add_option(
           "--camera", o.camera,
           "Reflect a camera: a V4L2 device (/dev/video0) or mock:PATH (an image or a folder of images)")
        ->type_name("DEVICE");
    cli.add_option("--stats", o.stats_every,
                   "Log fps, frame-time percentiles (p50/p95/p99), CPU time per frame, resident memory "
                   "and the render scale (render.scale, or the adaptive scale's: render.target_fps) every "
                   "SECONDS (default 5)")
        ->expected(0, 1)
        ->default_str("5")
        ->check(CLI::Range(0.1, 3600.0))
        ->type_name("SECONDS");
    cli.add_option("--gpio", o.gpio,
                   "Knob backend: gpiod (the GPIO header), or mock:PATH to drive knobs from a script or FIFO")
        ->type_name("BACKEND");
    cli.add_option("--state", o.state_path,
                   "Where knob changes are saved (default: $STATE_DIRECTORY/state.toml, else "
                   "~/.local/state/puddle/state.toml)")
        ->type_name("FILE");
    cli.add_option("--log-level", o.log_level, "trace, debug, info, warn, error")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}))
        ->type_name("LEVEL");
}

}  // namespace

Result<CliOptions> parse_command_line(int argc, const char* const* argv) {
    CliOptions o;
    std::string backend = "auto", size;
    CLI::App cli{kSummary, "puddle"};
    describe_command_line(cli, o, backend, size);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::fputs(cli.help().c_str(), stdout);
        return Error{"", ExitCode::Ok};
    } catch (const CLI::CallForVersion&) {
        std::printf("puddle %s\n", std::string(version()).c_str());
        return Error{"", ExitCode::Ok};
    } catch (const CLI::ParseError& e) {
        return make_error(ExitCode::Config, "puddle: {} (see puddle --help)", e.what());
    }
    // `preset` is no parameter but a new user's first try: --set preset=NAME is --preset NAME.
    std::erase_if(o.sets, [&](const std::string& a) {
        if (!a.starts_with("preset=")) return false;
        o.preset = a.substr(7);
        return true;
    });
    o.display.backend = platform::backend_from_name(backend).value_or(platform::BackendKind::Auto);
    if (!size.empty()) {
        auto s = parse_size(size);
        if (!s) return s.error();
        o.display.size = *s;
    }
    return o;
}

namespace {

// Text for man(7): backslashes and hyphens escaped, and a line that would start with a control
// character ('.' or '\'') guarded by the zero-width \&.
std::string roff(std::string_view text) {
    std::string out;
    bool line_start = true;
    for (const char c : text) {
        if (line_start && (c == '.' || c == '\'')) out += "\\&";
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else
            out += c;
        line_start = c == '\n';
    }
    return out;
}

// "-c, --config FILE" in roff: names bold, the value's name italic, optional values in brackets.
std::string option_heading(const CLI::Option& opt) {
    std::string names;
    for (const std::string& s : opt.get_snames())
        names += fmt::format("{}\\fB\\-{}\\fR", names.empty() ? "" : ", ", s);
    for (const std::string& l : opt.get_lnames())
        names += fmt::format("{}\\fB\\-\\-{}\\fR", names.empty() ? "" : ", ", roff(l));
    if (opt.get_expected_max() == 0) return names;  // a flag
    std::string value = opt.get_type_name();
    if (const auto colon = value.find(':'); colon != std::string::npos) value.resize(colon);
    const std::string shown = fmt::format("\\fI{}\\fR", roff(value));
    return names + (opt.get_expected_min() == 0 ? " [" + shown + "]" : " " + shown);
}

}  // namespace

std::string format_man_page() {
    CliOptions o;
    std::string backend, size;
    CLI::App cli{kSummary, "puddle"};
    describe_command_line(cli, o, backend, size);
    std::string page = fmt::format(
        ".TH PUDDLE 1 \"\" \"puddle {}\" \"User Commands\"\n"
        ".SH NAME\npuddle \\- rain falling on a puddle, a real\\-time display for digital signage\n"
        ".SH SYNOPSIS\n.B puddle\n[\\fIOPTIONS\\fR]\n"
        ".SH DESCRIPTION\n{}\n"
        ".PP\nRun by the package's systemd unit (puddle.service) it fills the screen through KMS with no "
        "desktop; "
        "it also runs in a desktop window, or headless, writing the last frame to a PNG.\n"
        ".SH OPTIONS\n",
        roff(version()), roff(kSummary));
    for (const CLI::Option* opt : cli.get_options()) {
        page += ".TP\n" + option_heading(*opt) + "\n";
        std::string help = opt->get_description();
        if (help.empty() && opt->get_name() == "--version") help = "Print the version and exit";
        page += roff(help) + ".\n";
    }
    page += ".SH EXAMPLES\n";
    for (const Example& e : kExamples)
        page += fmt::format(".TP\n.B {}\n{}.\n", roff(e.command), roff(e.what));
    page += ".SH LIVE TUNING\n" + roff(kLiveTuning);
    page += ".SH EXIT STATUS\n";
    for (const ExitStatus& e : kExitStatuses)
        page += fmt::format(".TP\n.B {}\n{}.\n", static_cast<int>(e.code), roff(e.meaning));
    page +=
        ".SH FILES\n"
        ".TP\n.I /etc/puddle/puddle.toml\nThe configuration; an edit applies while it runs.\n"
        ".TP\n.I /etc/puddle/presets/\nLooks of your own, beside the packaged ones in "
        "\\fI/usr/share/puddle/presets/\\fR.\n"
        ".TP\n.I /var/lib/puddle/state.toml\nWhat the knobs changed, kept across restarts (the service's "
        "StateDirectory).\n"
        ".SH SEE ALSO\n"
        "\\fI/usr/share/doc/puddle/README.md\\fR, and \\fBpuddle \\-\\-list\\-params\\fR for every "
        "parameter.\n";
    return page;
}

}  // namespace puddle::app
