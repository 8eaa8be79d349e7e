#include "app/app.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include "app/check.hpp"
#include "app/cli.hpp"
#include "app/engine.hpp"
#include "app/logging.hpp"
#include "app/process_setup.hpp"
#include "app/screenshot_file.hpp"
#include "app/signals.hpp"
#include "app/wall_screenshot.hpp"
#include "assets/image_io.hpp"
#include "io/gpio_backend.hpp"
#include "params/config_loader.hpp"
#include "params/param_docs.hpp"
#include "params/wall_check.hpp"
#include "platform/console_mode.hpp"
#include "schedule/zone_watch.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/common/frame_stats.hpp"
#include "systems/display/display_power.hpp"
#include "systems/puddle/puddle_plugin.hpp"
#include "systems/remote/remote_plugin.hpp"
#include "systems/service/service_notify.hpp"
#include "systems/service/service_plugin.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "systems/tuning/schedule_system.hpp"
#include "util/valid_utf8.hpp"
#include "util/version.hpp"

namespace puddle::app {

namespace {

constexpr long headless_default_frames = 180;
constexpr const char* headless_default_screenshot = "puddle-headless.png";

int fail(const Error& e) {
    spdlog::error("{}", e.message);
    return static_cast<int>(e.code);
}

}  // namespace

std::vector<Engine::Plugin> puddle_features(std::unique_ptr<StopSignals>& signals,
                                            systems::ServiceNotify& service, systems::LiveTuning& tuning) {
    return {
        // The stop and reload signals are the program's (app/signals.hpp); the service feature is handed
        // the reload one.
        [&](ecs::World& w, ecs::Schedule& s) {
            StopSignals& stop = w.adopt_resource<StopSignals>(std::move(signals));
            return systems::add_service_plugin(w, s, {[&stop] { return stop.take_reload(); }},
                                               std::move(service));
        },
        // The schedule asks live tuning for its changes, which live tuning then applies in the same frame.
        systems::add_schedule,
        [&](ecs::World& w, ecs::Schedule& s) { return systems::add_live_tuning(w, s, std::move(tuning)); },
        systems::add_display_power,
        systems::add_puddle_plugin,
        systems::add_remote_plugin,
    };
}

namespace {

// One --stats line. spdlog formats into a stack buffer, so this does not allocate either.
void log_stats(const systems::FrameStats::Summary& s, const systems::AdaptiveScale& adaptive) {
    const systems::MemoryStatus m = systems::read_memory_status();
    spdlog::info(
        "stats: {:.1f} fps over {} frames; frame ms p50 {:.2f} p95 {:.2f} p99 {:.2f} max {:.2f}; "
        "CPU ms/frame {:.2f} (frame loop thread {:.2f}); resident {:.1f} MB; render scale {:.2f}{}",
        s.fps, s.frames, s.p50_ms, s.p95_ms, s.p99_ms, s.max_ms, s.cpu_ms, s.main_cpu_ms, m.rss_kib / 1024.0,
        adaptive.scale,
        !adaptive.controller      ? ""
        : adaptive.short_at_floor ? " (adaptive; at render.min_scale and still short of render.target_fps)"
                                  : " (adaptive)");
}

}  // namespace

namespace {

// What a display run holds between its start, its frame loop and its finish.
struct DisplayRun {
    std::unique_ptr<Engine> engine;
    bool headless = false;   // nobody sees the frames: a fixed step each, a PNG at the end by default
    long frames = 0;         // 0: until stopped
    std::string screenshot;  // written at the finish; empty: none
    std::optional<WallScreenshot> wall_shot;
    // On a kiosk screen the text console must not draw over the picture; restored on every exit path
    // (declared after the engine, so it is restored before the display closes).
    std::optional<platform::ConsoleGraphicsMode> console;
    systems::FrameStats stats{5.0};
};

// Makes the engine with the binary's features and decides the run's frames and screenshot.
Result<DisplayRun> start(CliOptions& o, systems::LiveTuning& tuning) {
    const auto params = std::make_unique<params::Params>(tuning.layers.compose());
    using params::ParamId;
    o.display.card = params->get<ParamId::display_card>();
    o.display.connector = params->get<ParamId::display_connector>();
    o.display.mode = params->get<ParamId::display_mode>();

    spdlog::info("puddle {} starting", version());
    // Before any thread starts (main blocked the three already), so that every thread (Mesa's too) has
    // SIGINT, SIGTERM and SIGHUP blocked and they arrive only through the signalfd, one sent earlier too.
    auto signals = std::make_unique<StopSignals>();
    systems::ServiceNotify notify = systems::ServiceNotify::from_environment();
    auto engine = Engine::create(*params, o.display, {.background_compiles = true},
                                 puddle_features(signals, notify, tuning));
    if (!engine) return engine.error();
    DisplayRun run;
    run.engine = std::move(*engine);
    Engine& e = *run.engine;
    run.headless = !e.display().shows_frames();
    const std::string preset = e.world().resource<systems::LiveTuning>().layers.preset_name();
    const auto& caps = e.device().caps();
    const auto* zone = e.world().try_resource<systems::ZoneCheck>();
    spdlog::info("started: {}; GL: {} ({}); config: {}; preset: {}; time zone: {}", e.display().describe(),
                 caps.renderer, caps.version, config_path(o).empty() ? "none" : config_path(o),
                 preset.empty() ? "none" : preset,
                 zone ? zone->watch.zone().describe() : schedule::ZoneWatch().zone().describe());

    run.frames = o.frames.value_or(run.headless && !o.screenshot_at ? headless_default_frames : 0);
    run.screenshot = o.screenshot;
    if (run.headless && run.screenshot.empty() && !o.frames) run.screenshot = headless_default_screenshot;
    if (const auto problem = systems::wall_timing_problem(*params)) spdlog::warn("wall: {}", *problem);
    if (o.screenshot_at) {
        auto shot = arm_wall_screenshot(e.world(), *o.screenshot_at);
        if (!shot) return shot.error();
        run.wall_shot = *shot;
        if (o.screenshot.empty()) run.screenshot = "puddle-wall.png";
    }
    if (e.display().owns_the_console())
        if (auto console = platform::ConsoleGraphicsMode::enter()) run.console.emplace(std::move(*console));
    const systems::ServiceNotify& service = e.world().resource<systems::ServiceNotify>();
    if (service.enabled())
        spdlog::info(
            "systemd: READY after the first frame{}",
            service.watchdog_interval() > 0
                ? fmt::format(", watchdog every {:g} s while frames are presented", service.ping_interval())
                : std::string());
    run.stats = systems::FrameStats(o.stats_every > 0 ? o.stats_every : 5.0);
    return run;
}

// Frames until the count, a stop signal, a closed window or the wall screenshot's step. An error is a lost
// GPU or screen (the watchdog was pinged only after presents).
Result<void> frame_loop(DisplayRun& run, const CliOptions& o) {
    Engine& e = *run.engine;
    StopSignals& stop = e.world().resource<StopSignals>();
    using clock = std::chrono::steady_clock;
    const double fixed_dt = 1.0 / (o.fps_cap > 0 ? o.fps_cap : 60.0);
    auto last = clock::now();
    for (long n = 0; run.frames == 0 || n < run.frames; ++n) {
        if (o.stats_every > 0) {
            run.stats.tick();
            if (const auto s = run.stats.take_report())
                log_stats(*s, e.world().resource<systems::AdaptiveScale>());
        }
        if (stop.requested() || !e.display().poll_events()) {
            spdlog::info("stopping ({})",
                         stop.last_signal() ? strsignal(stop.last_signal()) : "display closed");
            return {};
        }
        // Headless runs advance a fixed step per frame, so the same command line gives the same image.
        const auto now = clock::now();
        // Under wall.clock = "realtime" the wall's clock sets the step whatever a frame's time is.
        const bool realtime = e.world().resource<params::Params>().get<params::ParamId::wall_clock>() ==
                              params::WallClockMode::realtime;
        const bool held = o.hold_after > 0 && n >= o.hold_after && !realtime;
        if (o.hold_after > 0 && n == o.hold_after) {
            if (held)
                spdlog::info("hold: the picture of frame {} stays on screen from now on (--hold-after)", n);
            else
                spdlog::warn(
                    "hold: --hold-after is ignored with wall.clock = \"realtime\": the wall's clock "
                    "sets the step");
        }
        const double dt = held                           ? 0.0
                          : run.headless || o.fixed_step ? fixed_dt
                                                         : std::chrono::duration<double>(now - last).count();
        last = now;
        if (!run.screenshot.empty() && run.frames != 0 && n == run.frames - 1) e.capture_next_frame();
        bool wall_shot_now = false;
        if (run.wall_shot) {
            auto due = wall_screenshot_due(e.world(), *run.wall_shot);
            if (!due) return due.error();
            wall_shot_now = *due;
        }
        if (wall_shot_now) e.capture_next_frame();
        if (auto r = e.frame(dt); !r) return r;
        if (wall_shot_now) return {};
        if (o.fps_cap > 0 && !run.headless)
            std::this_thread::sleep_until(now + std::chrono::duration_cast<clock::duration>(
                                                    std::chrono::duration<double>(1.0 / o.fps_cap)));
    }
    return {};
}

// The exit stage (STOPPING=1 to systemd, knob changes not yet saved: the user's data, saved on every
// path), the last statistics and the screenshot.
Result<void> finish(DisplayRun& run, const CliOptions& o) {
    Engine& e = *run.engine;
    e.shutdown();
    if (o.stats_every > 0) {
        if (const auto s = run.stats.summary(); s.frames > 0)
            log_stats(s, e.world().resource<systems::AdaptiveScale>());
        const systems::MemoryStatus m = systems::read_memory_status();
        spdlog::info(
            "stats: peak resident memory {:.1f} MB (VmHWM), {:.1f} MB now (VmRSS: {:.1f} MB anonymous, "
            "{:.1f} MB of the binary and shared libraries)",
            m.peak_kib / 1024.0, m.rss_kib / 1024.0, m.anon_kib / 1024.0, m.file_kib / 1024.0);
    }
    if (run.screenshot.empty()) return {};
    // Both branches are values: a `const Image&` bound to `cond ? read_frame() : captured()` was a copy.
    const assets::Image image = e.captured().empty() ? e.read_frame() : e.take_captured();
    if (auto r = write_screenshot(run.screenshot, image); !r) return r;
    const auto where = std::filesystem::absolute(run.screenshot).string();
    if (run.wall_shot)
        spdlog::info("wall: wave step {} written to {}", run.wall_shot->step, where);
    else if (run.headless && !o.frames)
        spdlog::info("headless: no display here; rendered {} frames to {}", run.frames, where);
    else
        spdlog::info("screenshot: {}", where);
    return {};
}

}  // namespace

int run(int argc, const char* const* argv) {
    setup_process();
    setup_logging(detect_log_style());

    auto options = parse_command_line(argc, argv);
    if (!options) {
        if (options.error().code == ExitCode::Ok) return 0;                         // --help, --version
        std::fprintf(stderr, "%s\n", valid_utf8(options.error().message).c_str());  // as log lines are
        return static_cast<int>(options.error().code);
    }
    CliOptions& o = *options;
    spdlog::set_level(spdlog::level::from_str(o.log_level));

    // A command that ends by itself has no reload to do; SIGINT and SIGTERM end it as any command.
    if (o.list_params || o.check || o.print_config) release_stop_signals_for_one_shot();
    if (o.list_params) {
        std::fputs((o.markdown ? params::format_params_markdown() : params::format_params_list()).c_str(),
                   stdout);
        return 0;
    }
    if (o.check) return run_check(o, config_path(o));
    auto tuning = load_tuning(o, o.print_config ? StartFor::print_config : StartFor::run);
    if (!tuning) return fail(tuning.error());
    if (o.print_config) {
        std::fputs(params::format_effective(tuning->layers.compose(), tuning->layers.preset_name(),
                                            tuning->layers.schedule_entries(),
                                            tuning->layers.active_schedule_presets())
                       .c_str(),
                   stdout);
        return 0;
    }

    auto started = start(o, *tuning);
    if (!started) return fail(started.error());
    DisplayRun& display_run = *started;
    if (auto ran = frame_loop(display_run, o); !ran) {
        display_run.engine->shutdown();  // the knob changes are the user's data: saved on this path too
        return fail(ran.error());
    }
    if (auto finished = finish(display_run, o); !finished) return fail(finished.error());
    return 0;
}

}  // namespace puddle::app
