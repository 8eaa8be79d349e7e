#include "app/startup.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/gpio_backend.hpp"
#include "params/config_loader.hpp"
#include "params/presets.hpp"
#include "params/wall_check.hpp"
#include "systems/tuning/schedule_system.hpp"

namespace puddle::app {

namespace {

constexpr const char* system_config = "/etc/puddle/puddle.toml";
constexpr const char* system_presets = "/etc/puddle/presets";

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

std::string config_path(const CliOptions& o) {
    if (!o.config_path.empty()) return o.config_path;
    return std::filesystem::exists(system_config) ? system_config : "";
}

std::vector<std::string> preset_folders_for(const std::string& config_path) {
    std::vector<std::string> folders{system_presets};
    if (!config_path.empty())
        folders.push_back((std::filesystem::path(config_path).parent_path() / "presets").string());
    return folders;
}

// Bad saved state is only warned about (restore_saved_state).
Result<systems::LiveTuning> load_tuning(const CliOptions& o, StartFor purpose) {
    const bool read_only = purpose != StartFor::run;
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
    // --check reads the state file itself, to report on it; --print-config shows what it restores.
    if ((!tuning.layers.config().knobs.empty() || remote) && purpose != StartFor::check) {
        tuning.state.emplace(o.state_path.empty() ? params::StateStore::default_path() : o.state_path);
        restore_saved_state(tuning, read_only);
    }
    if (!tuning.layers.config().knobs.empty() && purpose == StartFor::run) {
        auto gpio = io::make_gpio_backend(o.gpio);
        if (!gpio) return gpio.error();
        tuning.gpio = std::move(*gpio);
    }
    return tuning;
}

}  // namespace puddle::app
