// puddle-soak: the display running for a long time, compressed. It builds the engine the puddle binary
// builds (app::load_tuning and the live-tuning plugin, headless, a small frame), advances a fixed step
// of simulated time per frame, and on a schedule (soak_plan.hpp) rewrites the config file (the real
// inotify watcher and reload path), switches scene and drop model through it, and unplugs and replugs a
// mock camera by renaming its folder. Every few thousand frames it checks that GL raised no error, that
// the height field and the surface hold only finite values, and, after warm-up, that resident memory
// grew by less than 1 MB (at two checks in a row) and the open file descriptors are the same. Prints a
// summary; exits 1 on the first violation with one line naming it, 2 on bad flags or a failed start.
//
//   build/tests/puddle-soak                      # 10^6 frames (docs/testing.md, "Soak")
//   build/tests/puddle-soak --frames 27000 --check-every 1000   # ctest soak_short
#include <fmt/format.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>
#include <stdlib.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <string_view>
#include <utility>

#include "app/app.hpp"
#include "app/engine.hpp"
#include "app/logging.hpp"
#include "app/process_setup.hpp"
#include "assets/image_io.hpp"
#include "soak/process_sample.hpp"
#include "soak/soak_plan.hpp"
#include "systems/common/shown_look.hpp"
#include "systems/puddle/puddle_plugin.hpp"
#include "systems/sky/camera_system.hpp"
#include "systems/water/surface_system.hpp"
#include "systems/water/wave_system.hpp"

namespace puddle::soak {

namespace fs = std::filesystem;

namespace {

constexpr long rss_growth_limit_kib = 1024;

// Counts error lines whatever the console shows: an error logged by the engine (a reload refused, a
// field rebuild that failed) is a violation even when it did not crash anything.
class ErrorLineCounter final : public spdlog::sinks::base_sink<std::mutex> {
public:
    long count = 0;
    std::string first;

protected:
    void sink_it_(const spdlog::details::log_msg& msg) override {
        if (msg.level < spdlog::level::err) return;
        if (count++ == 0) first.assign(msg.payload.data(), msg.payload.size());
    }
    void flush_() override {}
};

// A fresh folder under $TMPDIR (else /tmp), removed with everything in it at the end.
class ScratchFolder {
public:
    ScratchFolder() {
        std::string pattern = (fs::temp_directory_path() / "puddle-soak-XXXXXX").string();
        if (mkdtemp(pattern.data())) path_ = pattern;
    }
    ~ScratchFolder() {
        std::error_code ec;
        if (!path_.empty()) fs::remove_all(path_, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

struct Options {
    SoakPlan plan;
    int width = 64, height = 36;
    std::string log_level = "warn";
};

struct Counters {
    long frames = 0;
    long reloads = 0, look_switches = 0, field_rebuilds = 0;
    long unplugs = 0, replugs = 0;
    long checks = 0;
    std::optional<ProcessSample> warm;  // the baseline, at the first check after warm-up
    long warm_frame = 0;
    ProcessSample first, last;
    long max_growth_kib = 0;
    int min_fds = 1 << 30, max_fds = 0;
    std::string memory_violation;  // the first check over the memory or fd limit
    bool last_check_over = false;  // the previous check's growth was over the limit
};

// The mock camera: two small images, so each poll that is due uploads a different one.
bool write_camera_folder(const fs::path& folder) {
    fs::create_directories(folder);
    for (int i = 0; i < 2; ++i) {
        assets::Image img = assets::Image::make(16, 8);
        for (std::size_t p = 0; p < img.data.size(); p += 4) {
            img.data[p] = static_cast<std::uint8_t>(60 + 120 * i);
            img.data[p + 1] = 90;
            img.data[p + 2] = static_cast<std::uint8_t>(200 - 100 * i);
            img.data[p + 3] = 255;
        }
        if (auto r = assets::write_png((folder / fmt::format("frame{}.png", i)).string(), img); !r) {
            std::fprintf(stderr, "soak: %s\n", r.error().message.c_str());
            return false;
        }
    }
    return true;
}

// Even reloads save as editors do (a new file renamed over the old: IN_MOVED_TO), odd ones rewrite the
// file in place (IN_CLOSE_WRITE): both paths of the watcher.
bool write_config(const SoakPlan& plan, const fs::path& path, long k, const fs::path& camera_folder) {
    const std::string text = plan.config(k, camera_folder.string());
    const fs::path target = k % 2 == 0 ? fs::path(path.string() + ".new") : path;
    {
        std::ofstream out(target, std::ios::trunc);
        out << text;
        if (!out.flush()) return false;
    }
    std::error_code ec;
    if (target != path) fs::rename(target, path, ec);
    return !ec;
}

bool same_look(const Look& a, const Look& b) {
    return std::string_view(a.scene) == b.scene && std::string_view(a.drops) == b.drops &&
           a.rain_overlay == b.rain_overlay;
}

std::size_t count_not_finite(const std::vector<float>& values) {
    std::size_t n = 0;
    for (const float v : values) n += std::isfinite(v) ? 0 : 1;
    return n;
}

double mb(long kib) {
    return static_cast<double>(kib) / 1024.0;
}

void print_summary(const Options& o, const Counters& c, double wall_s, const ErrorLineCounter& errors) {
    const double sim_s = static_cast<double>(c.frames) * o.plan.dt;
    std::printf("soak: %ld frames of %dx%d, %.0f s simulated (%.1f h), in %.1f s\n", c.frames, o.width,
                o.height, sim_s, sim_s / 3600.0, wall_s);
    std::printf("| what | value |\n|---|---|\n");
    std::printf("| frames | %ld (%.0f frames/s) |\n", c.frames,
                wall_s > 0 ? static_cast<double>(c.frames) / wall_s : 0.0);
    std::printf("| wall time | %.1f s |\n", wall_s);
    std::printf("| resident at the first check | %.1f MB |\n", mb(c.first.rss_kib));
    if (c.warm) {
        std::printf("| resident after warm-up (frame %ld) | %.1f MB |\n", c.warm_frame, mb(c.warm->rss_kib));
        std::printf("| resident at the end | %.1f MB (%+ld KiB) |\n", mb(c.last.rss_kib),
                    c.last.rss_kib - c.warm->rss_kib);
        std::printf("| largest growth after warm-up | %ld KiB (limit %ld KiB) |\n", c.max_growth_kib,
                    rss_growth_limit_kib);
        std::printf("| open fds | %d after warm-up, %d at the end (%d to %d over all checks) |\n",
                    c.warm->open_fds, c.last.open_fds, c.min_fds, c.max_fds);
    } else {
        std::printf("| after warm-up | not reached: the run ended before frame %ld |\n",
                    o.plan.warmup_frames());
    }
    std::printf("| peak resident (VmHWM) | %.1f MB |\n", mb(c.last.peak_kib));
    std::printf("| checks (GL errors, heights, memory, fds) | %ld, every %ld frames |\n", c.checks,
                o.plan.check_every);
    std::printf("| config reloads | %ld (each applied on the next frame) |\n", c.reloads);
    std::printf("| look switches (scene, drop model, overlay) | %ld |\n", c.look_switches);
    std::printf("| wave field rebuilds | %ld |\n", c.field_rebuilds);
    std::printf("| camera unplugs / replugs | %ld / %ld |\n", c.unplugs, c.replugs);
    std::printf("| error lines logged | %ld |\n", errors.count);
    if (!o.plan.reloads || !o.plan.look_switches || !o.plan.field_rebuilds || !o.plan.unplugs)
        std::printf("| left out (--without) | %s%s%s%s |\n", o.plan.reloads ? "" : "reloads ",
                    o.plan.look_switches ? "" : "looks ", o.plan.field_rebuilds ? "" : "rebuilds ",
                    o.plan.unplugs ? "" : "unplugs");
}

class Soak {
public:
    Soak(const Options& o, app::Engine& engine, const fs::path& config, const fs::path& camera)
        : o_(o),
          engine_(engine),
          config_(config),
          camera_(camera),
          unplugged_(camera.string() + ".unplugged") {}

    // The run; returns the first violation, or nothing.
    std::optional<std::string> run() {
        const SoakPlan& p = o_.plan;
        long k = 0;
        for (long n = 0; n < p.frames; ++n) {
            std::optional<long> reload;
            if (p.reloads && n > 0 && n % p.reload_every == 0) {
                reload = ++k;
                if (!write_config(p, config_, k, camera_))
                    return fmt::format("frame {}: cannot write {}", n, config_.string());
                ++c_.reloads;
                if (!same_look(p.look_for_reload(k - 1), p.look_for_reload(k))) ++c_.look_switches;
                if (p.wave_resolution_for_reload(k - 1) != p.wave_resolution_for_reload(k))
                    ++c_.field_rebuilds;
            }
            if (auto v = camera_schedule(n)) return v;
            if (auto r = engine_.frame(p.dt); !r) return fmt::format("frame {}: {}", n, r.error().message);
            c_.frames = n + 1;
            if (reload) {
                const int seed = engine_.params().get<params::ParamId::rain_seed>();
                if (seed != seed_for_reload(*reload))
                    return fmt::format(
                        "frame {}: config reload {} was not applied (rain.seed is {}, expected {})", n,
                        *reload, seed, seed_for_reload(*reload));
            }
            if ((n + 1) % p.check_every == 0 || n + 1 == p.frames)
                if (auto v = check(n + 1)) return v;
        }
        if (!c_.memory_violation.empty()) return c_.memory_violation;
        return std::nullopt;
    }

    const Counters& counters() const { return c_; }

private:
    // Unplug: the camera's folder is renamed away; replug: back. Before each, the feed must be in the
    // state the last one left it in, as the camera system saw it.
    std::optional<std::string> camera_schedule(long n) {
        const SoakPlan& p = o_.plan;
        const long phase = n % p.unplug_every;
        const auto& feed = engine_.world().resource<systems::CameraFeed>();
        std::error_code ec;
        if (!p.unplugs) return std::nullopt;
        if (phase == p.unplug_at) {
            if (!feed.streaming() || feed.losses != static_cast<std::uint64_t>(c_.unplugs))
                return fmt::format("frame {}: camera not streaming again after replug {} (losses seen: {})",
                                   n, c_.replugs, feed.losses);
            fs::rename(camera_, unplugged_, ec);
            ++c_.unplugs;
        } else if (phase == p.unplug_at + p.replug_after && c_.unplugs > c_.replugs) {
            if (feed.streaming() || feed.losses != static_cast<std::uint64_t>(c_.unplugs))
                return fmt::format("frame {}: camera unplug {} went unnoticed (losses seen: {})", n,
                                   c_.unplugs, feed.losses);
            fs::rename(unplugged_, camera_, ec);
            ++c_.replugs;
        }
        if (ec) return fmt::format("frame {}: camera folder: {}", n, ec.message());
        return std::nullopt;
    }

    std::optional<std::string> check(long frame) {
        ++c_.checks;
        gpu::Device& device = engine_.device();
        if (const std::string errors = device.take_errors(); !errors.empty())
            return fmt::format("frame {}: GL error: {}", frame, errors);
        auto& world = engine_.world();
        const std::vector<float> heights = world.resource<systems::WaveField>().read_heights(device);
        if (const std::size_t bad = count_not_finite(heights))
            return fmt::format("frame {}: height field: {} of {} values are NaN or Inf", frame, bad,
                               heights.size());
        const std::vector<float> surface = device.read_texture(world.resource<systems::Surface>().texture);
        if (const std::size_t bad = count_not_finite(surface))
            return fmt::format("frame {}: surface: {} of {} values are NaN or Inf", frame, bad,
                               surface.size());

        const ProcessSample s = sample_process();
        if (c_.checks == 1) c_.first = s;
        c_.last = s;
        c_.min_fds = std::min(c_.min_fds, s.open_fds);
        c_.max_fds = std::max(c_.max_fds, s.open_fds);
        if (!c_.warm) {
            if (frame >= o_.plan.warmup_frames()) c_.warm = s, c_.warm_frame = frame;
            std::printf("soak: frame %ld: resident %.1f MB, %d fds%s\n", frame, mb(s.rss_kib), s.open_fds,
                        c_.warm ? " (the baseline: warm-up ends)" : " (warming up)");
            std::fflush(stdout);
            return std::nullopt;
        }
        const long growth = s.rss_kib - c_.warm->rss_kib;
        c_.max_growth_kib = std::max(c_.max_growth_kib, growth);
        // Memory and fds do not stop the run: a long run's figures show whether growth levels off. Growth
        // counts when two checks in a row are over the limit: a leak keeps what it took, while memory that
        // a worker holds for a moment (a shader compile, a camera frame in flight) at one check is gone by
        // the next (soak_short met +1028 KiB once at frame 25 000, +0 at 24 000 and 26 000).
        const bool over = growth >= rss_growth_limit_kib;
        const bool was_over = std::exchange(c_.last_check_over, over);
        if (over && was_over && c_.memory_violation.empty())
            c_.memory_violation = fmt::format(
                "frame {}: resident memory grew {} KiB since warm-up at frame {} ({:.1f} -> {:.1f} MB; "
                "limit {} KiB)",
                frame, growth, c_.warm_frame, mb(c_.warm->rss_kib), mb(s.rss_kib), rss_growth_limit_kib);
        if (s.open_fds != c_.warm->open_fds && c_.memory_violation.empty())
            c_.memory_violation =
                fmt::format("frame {}: {} open file descriptors, {} after warm-up at frame {}", frame,
                            s.open_fds, c_.warm->open_fds, c_.warm_frame);
        std::printf("soak: frame %ld: resident %.1f MB (%+ld KiB since warm-up), %d fds\n", frame,
                    mb(s.rss_kib), growth, s.open_fds);
        std::fflush(stdout);
        return std::nullopt;
    }

    const Options& o_;
    app::Engine& engine_;
    fs::path config_, camera_, unplugged_;
    Counters c_;
};

int run(int argc, char** argv) {
    Options o;
    std::string size = "64x36";
    CLI::App cli{"puddle-soak: the display for a long time, compressed (docs/testing.md: Soak)",
                 "puddle-soak"};
    cli.add_option("--frames", o.plan.frames, "Frames to run (1/60 s of simulated time each)")
        ->check(CLI::Range(1L, 1'000'000'000L));
    cli.add_option("--check-every", o.plan.check_every,
                   "Frames between checks of GL errors, heights, memory and fds")
        ->check(CLI::Range(1L, 1'000'000L));
    cli.add_option("--size", size, "Frame size WIDTHxHEIGHT");
    std::vector<std::string> without;
    cli.add_option("--without", without, "Leave out: reloads, looks, rebuilds, unplugs (to find what grows)")
        ->check(CLI::IsMember({"reloads", "looks", "rebuilds", "unplugs"}));
    cli.add_option("--log-level", o.log_level,
                   "trace, debug, info, warn, error (error lines count as violations)");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e) == 0 ? 0 : 2;
    }
    for (const std::string& w : without) {
        if (w == "reloads") o.plan.reloads = false;
        if (w == "looks") o.plan.look_switches = false;
        if (w == "rebuilds") o.plan.field_rebuilds = false;
        if (w == "unplugs") o.plan.unplugs = false;
    }
    if (std::sscanf(size.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 16 || o.height < 16) {
        std::fprintf(stderr, "soak: --size %s: expected WIDTHxHEIGHT, each at least 16\n", size.c_str());
        return 2;
    }

    app::setup_logging(app::detect_log_style());
    const auto level = spdlog::level::from_str(o.log_level);
    auto errors = std::make_shared<ErrorLineCounter>();
    for (auto& sink : spdlog::default_logger()->sinks()) sink->set_level(level);
    spdlog::default_logger()->sinks().push_back(errors);
    spdlog::set_level(std::min(level, spdlog::level::err));

    ScratchFolder scratch;
    if (scratch.path().empty()) {
        std::fprintf(stderr, "soak: cannot make a folder under %s\n", fs::temp_directory_path().c_str());
        return 2;
    }
    const fs::path config = scratch.path() / "puddle.toml", camera = scratch.path() / "camera";
    if (!write_camera_folder(camera) || !write_config(o.plan, config, 0, camera)) return 2;

    app::CliOptions cli_options;
    cli_options.config_path = config.string();
    cli_options.display = {.backend = platform::BackendKind::Headless, .size = {o.width, o.height}};
    auto tuning = app::load_tuning(cli_options);
    if (!tuning) {
        std::fprintf(stderr, "soak: %s\n", tuning.error().message.c_str());
        return 2;
    }
    const params::Params initial = tuning->layers.compose();
    auto engine = app::Engine::create(initial, cli_options.display, {.background_compiles = true},
                                      {[&tuning](ecs::World& w, ecs::Schedule& s) {
                                           return systems::add_live_tuning(w, s, std::move(*tuning));
                                       },
                                       systems::add_puddle_plugin});
    if (!engine) {
        std::fprintf(stderr, "soak: %s\n", engine.error().message.c_str());
        return 2;
    }

    std::printf(
        "soak: %ld frames of %dx%d, config %s rewritten every %ld frames, camera unplugged every %ld; "
        "checks every %ld frames, warm-up %ld frames\n",
        o.plan.frames, o.width, o.height, config.c_str(), o.plan.reload_every, o.plan.unplug_every,
        o.plan.check_every, o.plan.warmup_frames());
    std::fflush(stdout);
    Soak soak(o, **engine, config, camera);
    const auto start = std::chrono::steady_clock::now();
    std::optional<std::string> violation = soak.run();
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!violation && errors->count > 0)
        violation = fmt::format("{} error line(s) logged; the first: {}", errors->count, errors->first);
    print_summary(o, soak.counters(), wall_s, *errors);
    if (violation) {
        std::printf("soak: FAIL: %s\n", violation->c_str());
        return 1;
    }
    std::printf("soak: PASS\n");
    return 0;
}

}  // namespace

}  // namespace puddle::soak

int main(int argc, char** argv) {
    puddle::app::setup_process();  // as the binary's main: the same malloc arenas, the same signals
    return puddle::soak::run(argc, argv);
}
