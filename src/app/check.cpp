#include "app/check.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "app/app.hpp"
#include "app/cli.hpp"
#include "app/startup.hpp"
#include "camera/format_negotiation.hpp"
#include "camera/v4l2_io.hpp"
#include "gpu/device.hpp"
#include "io/gpio_backend.hpp"
#include "params/config_loader.hpp"
#include "params/param_layers.hpp"
#include "params/state_store.hpp"
#include "platform/display.hpp"
#include "platform/drm_inventory.hpp"
#include "schedule/time_zone.hpp"
#include "schedule/zone_watch.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/tuning/schedule_system.hpp"
#include "util/version.hpp"

namespace puddle::app {

namespace {

struct Report {
    std::FILE* out;
    int problems = 0;
    void section(std::string_view name) {
        std::fprintf(out, "\n[%.*s]\n", static_cast<int>(name.size()), name.data());
    }
    void ok(const std::string& text) { std::fprintf(out, "  OK    %s\n", text.c_str()); }
    void absent(const std::string& text) {
        std::fprintf(out, "  --    %s\n", text.c_str());
    }  // fine, just not here
    void fix(const std::string& text) {
        std::fprintf(out, "  FIX   %s\n", text.c_str());
        ++problems;
    }
    void note(const std::string& text) { std::fprintf(out, "        %s\n", text.c_str()); }
};

std::string join(const std::vector<std::string>& items, std::size_t max) {
    std::string out;
    for (std::size_t i = 0; i < items.size() && i < max; ++i) out += (i ? ", " : "") + items[i];
    if (items.size() > max) out += fmt::format(" and {} more", items.size() - max);
    return out;
}

// The schedule: the entries active now and the next transition, in local time.
void check_schedule(Report& r, const params::Config& config) {
    r.section("schedule");
    const auto calendar = systems::make_calendar(config);
    if (!calendar) {
        r.absent("no [[schedule]] tables: the config applies at all hours");
        return;
    }
    if (const auto problem = schedule::time_zone_problem()) r.fix(*problem);
    r.ok("time zone: " + schedule::ZoneWatch().zone().describe());
    const double now = systems::system_wall_seconds();
    std::vector<std::string> active;
    for (int i : calendar->active_at(now))
        active.push_back(systems::describe_entry(config.schedule[static_cast<std::size_t>(i)]));
    r.ok(fmt::format("{} entr{}; now ({}): {}", config.schedule.size(),
                     config.schedule.size() == 1 ? "y" : "ies", systems::local_time_text(now),
                     active.empty() ? "none active" : join(active, 8) + " active"));
    if (const auto next = calendar->next_transition(now))
        r.note(fmt::format("next transition: {}", systems::describe_transition(config, *next)));
    else
        r.note("next transition: none in the next 8 days");
}

// The knob state a start would restore (read only): what it holds, or each value a start will drop.
void check_saved_state(Report& r, const CliOptions& o) {
    r.section("saved knob state");
    const params::StateStore store(o.state_path.empty() ? params::StateStore::default_path() : o.state_path);
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path path(store.path());
    if (!fs::exists(path, ec)) {
        // A link whose folder is missing (storage not mounted) cannot be written; one to a missing file can.
        if (fs::is_symlink(path, ec) &&
            !fs::is_directory(fs::absolute(path).parent_path() / fs::read_symlink(path, ec).parent_path(),
                              ec))
            r.fix(
                fmt::format("{}: a link to {}, whose folder does not exist (storage not mounted?): knob "
                            "changes cannot be saved",
                            store.path(), fs::read_symlink(path, ec).string()));
        else
            r.absent(fmt::format("{}: none yet (knob changes will be saved there)", store.path()));
        return;
    }
    const auto loaded = store.load();
    for (const std::string& problem : loaded.problems) r.fix(problem);
    if (!loaded.problems.empty())
        r.note(fmt::format(
            "a start sets this file aside as {}.bad-* and keeps its valid values; where it cannot, "
            "it leaves the file alone and saves no knob change",
            path.filename().string()));
    if (loaded.state)
        r.ok(fmt::format("{}: {} saved value(s){}{}", store.path(), loaded.state->entries.size(),
                         loaded.state->preset ? ", preset " : "", loaded.state->preset.value_or("")));
}

// The system clock as the kernel sees it (adjtimex): walls (wall.clock = "realtime") need it synchronised.
void check_clock(Report& r, const systems::ClockSync& sync, bool realtime,
                 const std::optional<std::string>& wall_problem) {
    r.section("clock");
    if (wall_problem) r.fix(*wall_problem);
    const std::string what = "system clock: " + systems::describe(sync);
    if (sync.synchronised)
        r.ok(what);
    else if (realtime)
        r.fix(what + "; wall.clock = \"realtime\" needs it: set up chrony or linuxptp (docs/video-walls.md)");
    else
        r.absent(what + " (only walls, wall.clock = \"realtime\", need it)");
    r.note(fmt::format("wall.clock = \"{}\"", realtime ? "realtime" : "frame"));
}

}  // namespace

std::vector<GpuFeatureLine> gpu_feature_lines(const gpu::Capabilities& caps, bool dmabuf_import) {
    std::vector<GpuFeatureLine> lines;
    auto feature = [&](bool have, const char* what, const char* without) {
        lines.push_back({have, have ? std::string(what) : fmt::format("{}: missing; {}", what, without)});
    };
    feature(caps.float_render_targets, "float render targets (wave field in RG32F)",
            "the wave field runs in fixed point (RG32I), the same picture");
    feature(caps.half_float_render_targets, "half-float render targets (HDR sky, surface)",
            "HDR skies are stored as RGBM, the surface as RGBA8");
    feature(caps.float_linear_filtering, "filtering of 32-bit float textures",
            "not needed: Puddle never filters them");
    feature(caps.timer_queries, "timer queries", "--stats and puddle-bench show CPU times only");
    feature(caps.external_images, "external images (OES_EGL_image_external_essl3)",
            "camera frames are copied");
    feature(dmabuf_import, "dmabuf import (EGL_EXT_image_dma_buf_import)",
            "camera frames are copied (glTexSubImage2D)");
    feature(caps.anisotropic_filtering, "anisotropic filtering", "the ground is filtered trilinearly");
    return lines;
}

int run_check(const CliOptions& o, const std::string& config_path, const CheckSources& sources) {
    Report r{sources.out};
    int exit_code = 0;
    if (spdlog::get_level() < spdlog::level::warn)
        spdlog::set_level(spdlog::level::warn);  // the report is the output
    std::fprintf(r.out, "puddle %s --check\n", std::string(version()).c_str());

    r.section("config");
    std::vector<params::KnobSpec> knobs;
    bool realtime = false;  // wall.clock in the config
    std::optional<std::string> wall_problem;
    if (config_path.empty()) {
        r.absent("no config file (/etc/puddle/puddle.toml does not exist): built-in defaults are used");
    }
    // Assembled as the run does (app/startup.hpp): the presets the config names, --preset and --set too.
    CliOptions as_run = o;
    as_run.config_path = config_path;
    auto tuning = load_tuning(as_run, StartFor::check);
    if (!tuning) {
        r.fix(tuning.error().message);
        exit_code = static_cast<int>(ExitCode::Config);
    } else {
        const params::Config& config = tuning->layers.config();
        if (!config_path.empty()) {
            const std::string& preset = tuning->layers.preset_name();
            r.ok(fmt::format("{}: valid ({} values, {} knobs{}{})", config_path, config.entries.size(),
                             config.knobs.size(), preset.empty() ? "" : ", preset ", preset));
            check_schedule(r, config);
        }
        knobs = config.knobs;
        const params::Params composed_params = tuning->layers.compose();
        realtime = composed_params.get<params::ParamId::wall_clock>() == params::WallClockMode::realtime;
        wall_problem = systems::wall_timing_problem(composed_params);
    }
    if (!knobs.empty()) check_saved_state(r, o);
    check_clock(r, sources.clock_sync(), realtime, wall_problem);

    r.section("display: DRM/KMS (--backend kms)");
    const auto cards = platform::list_drm_cards(sources.dri_folder);
    if (cards.empty())
        r.absent(fmt::format("no {}/card*: no KMS screen here (the window and headless backends still work)",
                             sources.dri_folder));
    for (const auto& card : cards) {
        switch (card.status) {
            case platform::DrmCardStatus::NoOutputs:  // a render-only GPU beside the display one: no fault
                r.absent(fmt::format("{}: {}", card.path, card.error));
                continue;
            case platform::DrmCardStatus::CannotOpen:
                r.fix(fmt::format("{}: {}", card.path, card.error));
                continue;
            case platform::DrmCardStatus::Display:
                break;
        }
        r.ok(fmt::format("{} ({}): {} connector(s)", card.path, card.driver, card.connectors.size()));
        for (const auto& c : card.connectors)
            r.note(fmt::format("{:<12} {}{}", c.name, c.connected ? "connected" : "not connected",
                               c.modes.empty() ? "" : ": " + join(c.modes, 6)));
    }

    r.section("GPU: EGL and OpenGL ES");
    {
        platform::DisplayOptions headless{.backend = platform::BackendKind::Headless, .size = {16, 16}};
        auto display = platform::create_display(headless);
        if (!display) {
            r.fix(display.error().message +
                  " (install Mesa: libegl-mesa0 libgl1-mesa-dri; check group render)");
            exit_code = exit_code ? exit_code : static_cast<int>(ExitCode::Display);
        } else {
            gpu::Device device;
            const auto& caps = device.caps();
            r.ok(fmt::format("{} / {} / {}", caps.vendor, caps.renderer, caps.version));
            const bool dmabuf = platform::current_display_has_extension("EGL_EXT_image_dma_buf_import");
            for (const GpuFeatureLine& line : gpu_feature_lines(caps, dmabuf)) {
                if (line.present)
                    r.ok(line.text);
                else
                    r.absent(line.text);
            }
        }
    }

    r.section("GPIO knobs (libgpiod)");
    auto gpio = io::make_gpio_backend(o.gpio);
    if (!gpio) {
        r.fix(gpio.error().message);
    } else {
        const auto chips = (*gpio)->chips();
        if (chips.empty()) r.absent("no GPIO chips (/dev/gpiochip*): knobs cannot work on this machine");
        for (const auto& chip : chips) {
            if (!chip.error.empty())
                r.fix(fmt::format("{}: {} (add the user to group gpio; install deploy/99-puddle-gpio.rules)",
                                  chip.name, chip.error));
            else
                r.ok(fmt::format("{} \"{}\", {} lines", chip.name, chip.label, chip.lines));
        }
        if (knobs.empty()) r.absent("no [[knob]] in the config");
        for (std::size_t i = 0; i < knobs.size(); ++i) {
            const auto& k = knobs[i];
            io::LineRequest req{k.chip, k.line, k.active_low, k.bias};
            auto a = (*gpio)->request(req);
            Result<std::unique_ptr<io::GpioLine>> b = std::unique_ptr<io::GpioLine>();
            if (a && k.kind == params::KnobKind::Encoder) {
                req.line = k.line_b;
                b = (*gpio)->request(req);
            }
            if (a && b)
                r.ok(fmt::format("knob {}: {}", i + 1, k.describe()));
            else
                r.fix(fmt::format("knob {} ({}): {}", i + 1, k.describe(),
                                  (!a ? a.error() : b.error()).message));
        }
    }

    r.section("cameras (V4L2)");
    std::vector<std::string> videos;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(sources.video_folder, ec))
        if (e.path().filename().string().starts_with("video")) videos.push_back(e.path().string());
    if (videos.empty())
        r.absent(fmt::format("no {}/video*: environment.source = \"camera\" would show the cubemap",
                             sources.video_folder));
    std::sort(videos.begin(), videos.end());
    for (const auto& v : videos) {
        auto offer = camera::device_offer(camera::system_v4l2_io(), v);
        if (!offer)
            r.fix(offer.error().message);
        else if (offer->empty())
            r.absent(fmt::format("{}: offers no capture formats (not a camera?)", v));
        else
            r.ok(fmt::format("{}: {}", v, camera::describe_offer(*offer)));
    }

    std::fprintf(r.out, "\n%s\n",
                 r.problems == 0 ? "Everything Puddle needs here is in order."
                                 : fmt::format("{} thing(s) to fix (FIX above).", r.problems).c_str());
    return exit_code;
}

}  // namespace puddle::app
