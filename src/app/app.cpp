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
#include "app/frame_stats.hpp"
#include "app/logging.hpp"
#include "app/process_setup.hpp"
#include "app/remote_plugin.hpp"
#include "app/screenshot_file.hpp"
#include "app/service_notify.hpp"
#include "app/service_plugin.hpp"
#include "app/signals.hpp"
#include "app/version.hpp"
#include "app/wall_screenshot.hpp"
#include "assets/image_io.hpp"
#include "io/gpio_backend.hpp"
#include "params/config_loader.hpp"
#include "params/param_docs.hpp"
#include "params/wall_check.hpp"
#include "platform/console_mode.hpp"
#include "schedule/zone_watch.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/display/display_power.hpp"
#include "systems/puddle/puddle_plugin.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "systems/tuning/schedule_system.hpp"
#include "util/valid_utf8.hpp"

namespace puddle::app {

namespace {

constexpr const char* system_config = "/etc/puddle/puddle.toml";
constexpr const char* system_presets = "/etc/puddle/presets";
constexpr long headless_default_frames = 180;
constexpr const char* headless_default_screenshot = "puddle-headless.png";

int fail(const Error& e) {
    spdlog::error("{}", e.message);
    return static_cast<int>(e.code);
}

// The config file in effect: --config, else the system one when it exists, else none.
std::string config_path(const CliOptions& o) {
    if (!o.config_path.empty()) return o.config_path;
    return std::filesystem::exists(system_config) ? system_config : "";
}

// Restores the saved knob state. A bad key is dropped and warned about, one line each, and the valid
// ones are kept; the original file is then set aside (never overwriting an earlier copy) and rewritten
// with what was valid, or, when it cannot be set aside, left as it is and never saved over. `read_only`
// (--print-config) reads and warns but changes nothing on disk.
void restore_saved_state(systems::LiveTuning& tuning, bool read_only) {
    auto loaded = tuning.state->load();
    for (const std::string& problem : loaded.problems) spdlog::warn("{}", problem);
    if (loaded.state) {
        if (auto r = tuning.layers.restore_state(*loaded.state); !r) spdlog::warn("{}", r.error().message);
        spdlog::info("state: {} knob value(s) restored from {}", loaded.state->entries.size(),
                     tuning.state->path());
    }
    if (loaded.problems.empty() || read_only) return;
    auto copy = tuning.state->set_aside();
    if (!copy) {  // the store now refuses to save: a file it could not keep is never replaced
        spdlog::warn("{}", copy.error().message);
        tuning.save_refused(copy.error().message);
        return;
    }
    spdlog::warn("state: the original is kept as {}; {} will hold the valid values", *copy,
                 tuning.state->path());
    tuning.save_soon();
}

}  // namespace

std::vector<std::string> preset_folders_for(const std::string& config_path) {
    std::vector<std::string> folders{system_presets};
    if (!config_path.empty())
        folders.push_back((std::filesystem::path(config_path).parent_path() / "presets").string());
    return folders;
}

// Bad saved state is only warned about (restore_saved_state).
Result<systems::LiveTuning> load_tuning(const CliOptions& o, bool read_only) {
    std::vector<params::ConfigEntry> command_line;
    if (o.seed) command_line.push_back({params::ParamId::rain_seed, *o.seed, 0});
    if (!o.camera.empty()) {  // shorthand for the two --set lines it stands for; a --set still wins
        for (const std::string& s :
             {std::string("environment.source=camera"), "environment.camera_device=" + o.camera}) {
            auto entry = params::parse_assignment(s);
            if (!entry) return entry.error();
            command_line.push_back(std::move(*entry));
        }
    }
    for (const std::string& s : o.sets) {
        auto entry = params::parse_assignment(s);
        if (!entry) return entry.error();
        command_line.push_back(std::move(*entry));
    }
    const std::string path = config_path(o);
    const std::vector<std::string> preset_folders = preset_folders_for(path);
    systems::LiveTuning tuning(
        params::ParamLayers(params::Presets::load(preset_folders), std::move(command_line)));
    tuning.config_path = path;
    tuning.preset_folders = preset_folders;
    if (!o.preset.empty())
        if (auto r = tuning.layers.set_command_line_preset(o.preset); !r) return r.error();
    if (!path.empty()) {
        auto config = params::load_config_file(path);
        if (!config) return config.error();
        const std::size_t values = config->entries.size(), knobs = config->knobs.size();
        if (auto r = tuning.layers.set_config(std::move(*config)); !r) return r.error();
        spdlog::info("config: {} ({} values, {} knobs{}{})", path, values, knobs,
                     tuning.layers.preset_name().empty() ? "" : ", preset ", tuning.layers.preset_name());
        // The first frame, and --print-config, already show what the schedule says now.
        systems::activate_schedule(tuning, systems::system_wall_seconds());
    } else {
        spdlog::info("config: none given, built-in defaults (see puddle --list-params)");
        if (auto r = params::check_wall(tuning.layers.compose(), {}); !r) return r.error();  // --set alone
    }
    if (auto r = io::check_gpio_spec(o.gpio); !r) return r.error();
    // Knob and remote values share the state file (ParamLayers); without either there is none.
    const bool remote = tuning.layers.compose().get<params::ParamId::remote_enabled>();
    if (!tuning.layers.config().knobs.empty() || remote) {
        tuning.state.emplace(o.state_path.empty() ? params::StateStore::default_path() : o.state_path);
        restore_saved_state(tuning, read_only);
    }
    if (!tuning.layers.config().knobs.empty()) {
        auto gpio = io::make_gpio_backend(o.gpio);
        if (!gpio) return gpio.error();
        tuning.gpio = std::move(*gpio);
    }
    return tuning;
}

std::vector<Engine::Plugin> puddle_features(std::unique_ptr<StopSignals>& signals, ServiceNotify& service,
                                            systems::LiveTuning& tuning) {
    return {
        [&](ecs::World& w, ecs::Schedule& s) {
            return add_service_plugin(w, s, std::move(signals), std::move(service));
        },
        [&](ecs::World& w, ecs::Schedule& s) { return systems::add_live_tuning(w, s, std::move(tuning)); },
        systems::add_schedule,
        systems::add_display_power,
        systems::add_puddle_plugin,
        add_remote_plugin,
    };
}

namespace {

// One --stats line. spdlog formats into a stack buffer, so this does not allocate either.
void log_stats(const FrameStats::Summary& s, const systems::AdaptiveScale& adaptive) {
    const MemoryStatus m = read_memory_status();
    spdlog::info(
        "stats: {:.1f} fps over {} frames; frame ms p50 {:.2f} p95 {:.2f} p99 {:.2f} max {:.2f}; "
        "CPU ms/frame {:.2f} (frame loop thread {:.2f}); resident {:.1f} MB; render scale {:.2f}{}",
        s.fps, s.frames, s.p50_ms, s.p95_ms, s.p99_ms, s.max_ms, s.cpu_ms, s.main_cpu_ms, m.rss_kib / 1024.0,
        adaptive.scale, adaptive.controller ? " (adaptive)" : "");
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
    auto tuning = load_tuning(o, o.print_config);
    if (!tuning) return fail(tuning.error());
    const auto params = std::make_unique<params::Params>(tuning->layers.compose());
    if (o.print_config) {
        std::fputs(
            params::format_effective(*params, tuning->layers.preset_name(), tuning->layers.schedule_entries(),
                                     tuning->layers.active_schedule_presets())
                .c_str(),
            stdout);
        return 0;
    }

    using params::ParamId;
    o.display.card = params->get<ParamId::display_card>();
    o.display.connector = params->get<ParamId::display_connector>();
    o.display.mode = params->get<ParamId::display_mode>();

    spdlog::info("puddle {} starting", version());
    // Before any thread starts (main blocked the three already), so that every thread (Mesa's too) has
    // SIGINT, SIGTERM and SIGHUP blocked and they arrive only through the signalfd, one sent earlier too.
    auto signals = std::make_unique<StopSignals>();
    ServiceNotify notify = ServiceNotify::from_environment();
    auto engine = Engine::create(*params, o.display, {.background_compiles = true},
                                 puddle_features(signals, notify, *tuning));
    if (!engine) return fail(engine.error());
    Engine& e = **engine;
    StopSignals& stop = e.world().resource<StopSignals>();
    const ServiceNotify& service = e.world().resource<ServiceNotify>();
    const bool headless = !e.display().shows_frames();
    const std::string preset = e.world().resource<systems::LiveTuning>().layers.preset_name();
    const auto& caps = e.device().caps();
    const auto* zone = e.world().try_resource<systems::ZoneCheck>();
    spdlog::info("started: {}; GL: {} ({}); config: {}; preset: {}; time zone: {}", e.display().describe(),
                 caps.renderer, caps.version, config_path(o).empty() ? "none" : config_path(o),
                 preset.empty() ? "none" : preset,
                 zone ? zone->watch.zone().describe() : schedule::ZoneWatch().zone().describe());

    long frames =
        o.frames.value_or(headless && !o.screenshot_at ? headless_default_frames : 0);  // 0: until stopped
    std::string screenshot = o.screenshot;
    if (headless && screenshot.empty() && !o.frames) screenshot = headless_default_screenshot;
    if (const auto problem = systems::wall_timing_problem(*params)) spdlog::warn("wall: {}", *problem);
    std::optional<WallScreenshot> wall_shot;
    if (o.screenshot_at) {
        auto shot = arm_wall_screenshot(e.world(), *o.screenshot_at);
        if (!shot) return fail(shot.error());
        wall_shot = *shot;
        if (o.screenshot.empty()) screenshot = "puddle-wall.png";
    }

    // On a kiosk screen the text console must not draw over the picture; restored on every exit path.
    const auto console =
        e.display().owns_the_console() ? platform::ConsoleGraphicsMode::enter() : std::nullopt;
    if (service.enabled())
        spdlog::info(
            "systemd: READY after the first frame{}",
            service.watchdog_interval() > 0
                ? fmt::format(", watchdog every {:g} s while frames are presented", service.ping_interval())
                : std::string());
    using clock = std::chrono::steady_clock;
    const double fixed_dt = 1.0 / (o.fps_cap > 0 ? o.fps_cap : 60.0);
    auto last = clock::now();
    FrameStats stats(o.stats_every > 0 ? o.stats_every : 5.0);
    for (long n = 0; frames == 0 || n < frames; ++n) {
        if (o.stats_every > 0) {
            stats.tick();
            if (const auto s = stats.take_report())
                log_stats(*s, e.world().resource<systems::AdaptiveScale>());
        }
        if (stop.requested() || !e.display().poll_events()) {
            spdlog::info("stopping ({})",
                         stop.last_signal() ? strsignal(stop.last_signal()) : "display closed");
            break;
        }
        // Headless runs advance a fixed step per frame, so the same command line gives the same image.
        const auto now = clock::now();
        const double dt =
            headless || o.fixed_step ? fixed_dt : std::chrono::duration<double>(now - last).count();
        last = now;
        if (!screenshot.empty() && frames != 0 && n == frames - 1) e.capture_next_frame();
        bool wall_shot_now = false;
        if (wall_shot) {
            auto due = wall_screenshot_due(e.world(), *wall_shot);
            if (!due) {
                e.shutdown();
                return fail(due.error());
            }
            wall_shot_now = *due;
        }
        if (wall_shot_now) e.capture_next_frame();
        if (auto r = e.frame(dt); !r) {  // a lost GPU or screen; the watchdog was pinged only after presents
            e.shutdown();                // knob changes are the user's data: saved on this path too
            return fail(r.error());
        }
        if (wall_shot_now) break;
        if (o.fps_cap > 0 && !headless)
            std::this_thread::sleep_until(now + std::chrono::duration_cast<clock::duration>(
                                                    std::chrono::duration<double>(1.0 / o.fps_cap)));
    }
    e.shutdown();  // STOPPING=1 to systemd, knob changes not yet saved
    if (o.stats_every > 0) {
        if (const auto s = stats.summary(); s.frames > 0)
            log_stats(s, e.world().resource<systems::AdaptiveScale>());
        const MemoryStatus m = read_memory_status();
        spdlog::info(
            "stats: peak resident memory {:.1f} MB (VmHWM), {:.1f} MB now (VmRSS: {:.1f} MB anonymous, "
            "{:.1f} MB of the binary and shared libraries)",
            m.peak_kib / 1024.0, m.rss_kib / 1024.0, m.anon_kib / 1024.0, m.file_kib / 1024.0);
    }
    if (!screenshot.empty()) {
        // Both branches are values: a `const Image&` bound to `cond ? read_frame() : captured()` was a copy.
        const assets::Image image = e.captured().empty() ? e.read_frame() : e.take_captured();
        if (auto r = write_screenshot(screenshot, image); !r) return fail(r.error());
        const auto where = std::filesystem::absolute(screenshot).string();
        if (wall_shot)
            spdlog::info("wall: wave step {} written to {}", wall_shot->step, where);
        else if (headless && !o.frames)
            spdlog::info("headless: no display here; rendered {} frames to {}", frames, where);
        else
            spdlog::info("screenshot: {}", where);
    }
    return 0;
}

}  // namespace puddle::app
