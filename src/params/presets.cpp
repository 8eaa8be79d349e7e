#include "params/presets.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "params/toml_limits.hpp"
#include "util/safe_quote.hpp"

namespace puddle::params {

Presets Presets::load(std::span<const std::string> folders) {
    Presets p;
    auto add = [&p](std::string name, std::string origin, std::string text, std::optional<Error> error = {}) {
        Entry entry{std::move(name), std::move(origin), std::move(text), std::move(error)};
        auto it = std::find_if(p.entries_.begin(), p.entries_.end(),
                               [&](const Entry& e) { return e.name == entry.name; });
        if (it != p.entries_.end())
            *it = std::move(entry);
        else
            p.entries_.push_back(std::move(entry));
    };
    for (const EmbeddedPreset& e : embedded_presets())
        add(e.name, fmt::format("presets/{}.toml (built in)", e.name), e.text);
    for (const std::string& folder : folders) {
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec)) continue;
        std::size_t files = 0;
        for (const auto& file : std::filesystem::directory_iterator(folder, ec)) {
            if (file.path().extension() != ".toml") continue;
            if (++files > max_preset_files) {  // each is held in memory, up to 1 MiB
                spdlog::warn("presets: {} holds more than {} .toml files; the rest are ignored", folder,
                             max_preset_files);
                break;
            }
            // Read with the TOML input limits; a file past them keeps its error for get() to report, so
            // choosing that preset fails with the limit named, as a config file would.
            auto text = read_toml_file(file.path().string());
            if (!text)
                add(file.path().stem().string(), file.path().string(), {}, text.error());
            else
                add(file.path().stem().string(), file.path().string(), std::move(*text));
        }
    }
    for (const Entry& e : p.entries_) p.names_.push_back(e.name);
    std::sort(p.names_.begin(), p.names_.end());
    return p;
}

bool Presets::contains(std::string_view name) const {
    return std::find(names_.begin(), names_.end(), name) != names_.end();
}

Result<Config> Presets::get(std::string_view name) const {
    auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.name == name; });
    if (it == entries_.end())
        return make_error(ExitCode::Config, "preset '{}' does not exist (presets: {})", safe_quote(name),
                          fmt::join(names_, ", "));
    if (it->read_error) return *it->read_error;
    auto config = parse_config(it->text, it->origin);
    if (!config) return config.error();
    if (config->preset || !config->knobs.empty())
        return make_error(ExitCode::Config,
                          "config: {}: a preset holds parameters only (no preset = or [[knob]])", it->origin);
    return config;
}

std::string Presets::step(std::string_view current, int direction) const {
    if (names_.empty()) return {};
    auto it = std::find(names_.begin(), names_.end(), current);
    if (it == names_.end()) return direction >= 0 ? names_.front() : names_.back();
    const auto n = static_cast<long>(names_.size());
    const long k = ((it - names_.begin()) + direction % n + n) % n;
    return names_[static_cast<std::size_t>(k)];
}

}  // namespace puddle::params
