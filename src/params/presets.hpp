#pragma once
// Presets: named looks (config/presets/*.toml, embedded into the binary at build time), selected with
// `preset = "downpour"` in the config or stepped through with a knob's button. A preset file in a
// preset folder (/etc/puddle/presets/, or presets/ beside the config file) adds a look or replaces a
// built-in one of the same name.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "params/config_loader.hpp"
#include "util/result.hpp"

namespace puddle::params {

struct EmbeddedPreset {
    const char* name;
    const char* text;
};
std::span<const EmbeddedPreset> embedded_presets();  // generated

class Presets {
public:
    // Preset files read from one folder, at most (each up to 1 MiB, toml_limits.hpp).
    static constexpr std::size_t max_preset_files = 64;

    // The built-in presets, then `*.toml` files in each folder that exists.
    static Presets load(std::span<const std::string> folders);
    // Sorted names.
    const std::vector<std::string>& names() const { return names_; }
    bool contains(std::string_view name) const;
    // The preset's values, validated like a config file; presets hold parameters only.
    Result<Config> get(std::string_view name) const;
    // The preset `direction` (+1/-1) places from `current` in name order, wrapping; the first when
    // `current` is none of them.
    std::string step(std::string_view current, int direction) const;

private:
    struct Entry {
        std::string name, origin, text;
        std::optional<Error> read_error;  // the file could not be read (or is past the input limits)
    };
    std::vector<Entry> entries_;
    std::vector<std::string> names_;
};

}  // namespace puddle::params
