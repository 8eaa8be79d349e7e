#include "params/presets.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace puddle::params {

Presets Presets::load(std::span<const std::string> folders) {
    Presets p;
    auto add = [&p](std::string name, std::string origin, std::string text) {
        auto it = std::find_if(p.entries_.begin(), p.entries_.end(), [&](const Entry& e) { return e.name == name; });
        if (it != p.entries_.end()) *it = {std::move(name), std::move(origin), std::move(text)};
        else p.entries_.push_back({std::move(name), std::move(origin), std::move(text)});
    };
    for (const EmbeddedPreset& e : embedded_presets())
        add(e.name, fmt::format("presets/{}.toml (built in)", e.name), e.text);
    for (const std::string& folder : folders) {
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec)) continue;
        for (const auto& file : std::filesystem::directory_iterator(folder, ec)) {
            if (file.path().extension() != ".toml") continue;
            std::ifstream in(file.path());
            std::ostringstream text;
            text << in.rdbuf();
            add(file.path().stem().string(), file.path().string(), text.str());
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
        return make_error(ExitCode::Config, "preset '{}' does not exist (presets: {})", name, fmt::join(names_, ", "));
    auto config = parse_config(it->text, it->origin);
    if (!config) return config.error();
    if (config->preset || !config->knobs.empty())
        return make_error(ExitCode::Config, "config: {}: a preset holds parameters only (no preset = or [[knob]])",
                          it->origin);
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
