#include "app/app.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "app/cli.hpp"
#include "app/engine.hpp"
#include "app/signals.hpp"
#include "app/version.hpp"
#include "assets/image_io.hpp"
#include "params/config_loader.hpp"
#include "params/param_docs.hpp"

namespace puddle::app {

namespace {

constexpr const char* system_config = "/etc/puddle/puddle.toml";
constexpr long headless_default_frames = 180;
constexpr const char* headless_default_screenshot = "puddle-headless.png";

int fail(const Error& e) {
    spdlog::error("{}", e.message);
    return static_cast<int>(e.code);
}

// Defaults < config file < --seed, --camera < --set.
Result<params::Params> load_params(const CliOptions& o) {
    params::Params params;
    std::string path = o.config_path;
    if (path.empty() && std::filesystem::exists(system_config)) path = system_config;
    if (!path.empty()) {
        auto config = params::load_config_file(path);
        if (!config) return config.error();
        params::apply_config(*config, params);
        spdlog::info("config: {} ({} values)", path, config->entries.size());
    } else {
        spdlog::info("config: none given, built-in defaults (see puddle --list-params)");
    }
    if (o.seed) params.set(params::ParamId::rain_seed, *o.seed, params::ParamSource::CommandLine);
    if (!o.camera.empty()) {  // shorthand for the two --set lines it stands for
        params.set(params::ParamId::environment_source, std::string("camera"), params::ParamSource::CommandLine);
        params.set(params::ParamId::environment_camera_device, o.camera, params::ParamSource::CommandLine);
    }
    for (const std::string& s : o.sets) {
        auto entry = params::parse_assignment(s);
        if (!entry) return entry.error();
        params.set(entry->id, entry->value, params::ParamSource::CommandLine);
    }
    return params;
}

}  // namespace

int run(int argc, const char* const* argv) {
    auto logger = spdlog::stderr_color_mt("puddle");
    spdlog::set_default_logger(logger);
    spdlog::set_pattern("%^%l%$: %v");

    auto options = parse_command_line(argc, argv);
    if (!options) {
        if (options.error().code == ExitCode::Ok) return 0;  // --help, --version
        std::fprintf(stderr, "%s\n", options.error().message.c_str());
        return static_cast<int>(options.error().code);
    }
    CliOptions& o = *options;
    spdlog::set_level(spdlog::level::from_str(o.log_level));

    if (o.list_params) {
        std::fputs((o.markdown ? params::format_params_markdown() : params::format_params_list()).c_str(), stdout);
        return 0;
    }
    auto params = load_params(o);
    if (!params) return fail(params.error());
    if (o.print_config) {
        std::fputs(params::format_effective(*params).c_str(), stdout);
        return 0;
    }

    using params::ParamId;
    o.display.card = params->s(ParamId::display_card);
    o.display.connector = params->s(ParamId::display_connector);
    o.display.mode = params->s(ParamId::display_mode);

    spdlog::info("puddle {} starting", version());
    auto engine = Engine::create(*params, o.display);
    if (!engine) return fail(engine.error());
    Engine& e = **engine;
    const bool headless = e.display().kind() == platform::BackendKind::Headless;
    spdlog::info("{}", e.display().describe());

    long frames = o.frames.value_or(headless ? headless_default_frames : 0);  // 0: run until stopped
    std::string screenshot = o.screenshot;
    if (headless && screenshot.empty() && !o.frames) screenshot = headless_default_screenshot;

    StopSignals stop;
    using clock = std::chrono::steady_clock;
    const double fixed_dt = 1.0 / (o.fps_cap > 0 ? o.fps_cap : 60.0);
    auto last = clock::now();
    for (long n = 0; frames == 0 || n < frames; ++n) {
        if (stop.requested() || !e.display().poll_events()) {
            spdlog::info("stopping ({})", stop.last_signal() ? strsignal(stop.last_signal()) : "display closed");
            break;
        }
        // Headless runs advance a fixed step per frame, so the same command line gives the same image.
        const auto now = clock::now();
        const double dt = headless ? fixed_dt : std::chrono::duration<double>(now - last).count();
        last = now;
        if (!screenshot.empty() && frames != 0 && n == frames - 1) e.capture_next_frame();
        if (auto r = e.frame(dt); !r) return fail(r.error());
        if (o.fps_cap > 0 && !headless)
            std::this_thread::sleep_until(now + std::chrono::duration_cast<clock::duration>(
                                                    std::chrono::duration<double>(1.0 / o.fps_cap)));
    }
    if (!screenshot.empty()) {
        const assets::Image& image = e.captured().empty() ? e.read_frame() : e.captured();
        if (auto r = assets::write_png(screenshot, image); !r) return fail(r.error());
        const auto where = std::filesystem::absolute(screenshot).string();
        if (headless && !o.frames)
            spdlog::info("headless: no display here; rendered {} frames to {}", frames, where);
        else
            spdlog::info("screenshot: {}", where);
    }
    return 0;
}

}  // namespace puddle::app
