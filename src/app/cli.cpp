#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/version.hpp"

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

}  // namespace

Result<CliOptions> parse_command_line(int argc, const char* const* argv) {
    CliOptions o;
    CLI::App cli{
        "Puddle: rain falling on a puddle, for signage screens.\n"
        "Renders fullscreen on a KMS display, in a desktop window, or headless to a PNG.\n"
        "Tune it with a TOML config (see config/puddle.toml) or --set; list every parameter with "
        "--list-params.",
        "puddle"};
    cli.footer(
        "Examples:\n"
        "  puddle                                  pick a display by itself (kms, window, else headless)\n"
        "  puddle --backend headless --frames 300 --screenshot rain.png\n"
        "  puddle --config /etc/puddle/puddle.toml --set rain.drop_count=40 --set water.turbidity=0.2\n"
        "  puddle --config my.toml --print-config     every value and where it came from (preset, config, "
        "knob...)\n"
        "Live tuning: an edited config file applies within a moment (or send SIGHUP); a bad edit is logged\n"
        "with file:line and the last good config keeps running. `preset = \"downpour\"` in the config picks\n"
        "a look; [[knob]] tables wire GPIO encoders, buttons and switches (see config/puddle.toml).\n"
        "Exit codes: 0 ok, 1 runtime failure, 2 bad config or flag, 3 missing or bad image, 4 no display,\n"
        "5 out of GPU memory (a texture or buffer did not fit: try a smaller size).");
    cli.set_version_flag("--version", std::string("puddle ") + std::string(version()));
    std::string backend = "auto", size;
    cli.add_option("--config,-c", o.config_path,
                   "TOML config file (default: /etc/puddle/puddle.toml if present)");
    cli.add_option("--set,-s", o.sets,
                   "Set a parameter, e.g. --set rain.drop_count=20 (repeatable; wins over the config)");
    cli.add_flag("--list-params", o.list_params,
                 "Print every parameter with its type, default, range and meaning");
    cli.add_flag("--markdown", o.markdown,
                 "With --list-params: print the Markdown table docs/parameters.md carries");
    cli.add_flag("--check", o.check,
                 "Check this machine (config, screens, GPU, GPIO, cameras; the schedule's active entries and "
                 "next transition): OK or what to fix, then exit");
    cli.add_flag("--print-config", o.print_config,
                 "Print every effective value and where it came from, then exit");
    cli.add_option("--backend,-b", backend,
                   "Display: auto, kms (fullscreen on a screen), window (desktop), headless")
        ->check(CLI::IsMember({"auto", "kms", "window", "headless"}));
    cli.add_option("--size", size,
                   "Render size WIDTHxHEIGHT (headless default 640x360; kms: picks that mode)");
    cli.add_flag("--fullscreen", o.display.fullscreen, "window backend: fill the screen");
    cli.add_option("--frames,-n", o.frames,
                   "Stop after N frames (headless default: 180, then write a PNG; 0: run until stopped)")
        ->check(CLI::Range(0L, 1000000000L));
    cli.add_option("--screenshot", o.screenshot,
                   "Write the last frame to this file: JPEG when it ends in .jpg or .jpeg, else PNG");
    cli.add_option("--screenshot-at", o.screenshot_at,
                   "Video walls (wall.clock = \"realtime\"): write the frame of the wave step this wall time "
                   "falls in (seconds since the Unix epoch, e.g. $(date -d '+30 sec' +%s)) to --screenshot "
                   "(default puddle-wall.png), then exit. Run it on every screen with the same time to check "
                   "the wall's alignment: all write the same step")
        ->check(CLI::Range(0.0, 1e11));
    cli.add_option("--seed", o.seed, "Rain seed (same as --set rain.seed=N): same seed, same rain")
        ->check(CLI::Range(0, 2147483647));
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
            "", "a number"));
    cli.add_flag(
        "--fixed-step", o.fixed_step,
        "Advance simulated time by 1/60 s (or 1/fps-cap) per frame on any backend, as headless runs do: "
        "frame N on a screen is then the same picture as a headless render of N frames");
    cli.add_option(
        "--camera", o.camera,
        "Reflect a camera: a V4L2 device (/dev/video0) or mock:PATH (an image or a folder of images)");
    cli.add_option("--stats", o.stats_every,
                   "Log fps, frame-time percentiles (p50/p95/p99), CPU time per frame, resident memory "
                   "and the render scale (render.scale, or the adaptive scale's: render.target_fps) every "
                   "SECONDS (default 5)")
        ->expected(0, 1)
        ->default_str("5")
        ->check(CLI::Range(0.1, 3600.0));
    cli.add_option(
        "--gpio", o.gpio,
        "Knob backend: gpiod (the GPIO header), or mock:PATH to drive knobs from a script or FIFO");
    cli.add_option("--state", o.state_path,
                   "Where knob changes are saved (default: $STATE_DIRECTORY/state.toml, else "
                   "~/.local/state/puddle/state.toml)");
    cli.add_option("--log-level", o.log_level, "trace, debug, info, warn, error")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error"}));
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
    if (backend == "kms")
        o.display.backend = platform::BackendKind::Kms;
    else if (backend == "window")
        o.display.backend = platform::BackendKind::Window;
    else if (backend == "headless")
        o.display.backend = platform::BackendKind::Headless;
    if (!size.empty()) {
        auto s = parse_size(size);
        if (!s) return s.error();
        o.display.size = *s;
    }
    return o;
}

}  // namespace puddle::app
