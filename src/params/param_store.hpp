#pragma once
// Params: the current value of every declared parameter and where it came from. A World resource that
// the input stage writes (config, --set, later knobs) and systems read. `revision` changes whenever a
// value does, so a system can rebuild what depends on it without comparing every value each frame.

#include <array>
#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

#include "params/registry.hpp"

namespace puddle::params {

// Lowest to highest precedence; a value from a higher source is never overwritten by a lower one.
enum class ParamSource : std::uint8_t { Default, Preset, Config, Knob, CommandLine };
std::string_view source_name(ParamSource s);

class Params {
public:
    Params();  // every value at its declared default

    bool b(ParamId id) const { return std::get<bool>(at(id)); }
    int i(ParamId id) const { return std::get<int>(at(id)); }
    float f(ParamId id) const { return std::get<float>(at(id)); }
    glm::vec3 v3(ParamId id) const { return std::get<glm::vec3>(at(id)); }
    const std::string& s(ParamId id) const { return std::get<std::string>(at(id)); }
    const ParamValue& at(ParamId id) const { return values_[index(id)]; }
    ParamSource source(ParamId id) const { return sources_[index(id)]; }

    // Sets a value that was validated against its declaration. Returns false (and changes nothing) when
    // the current value comes from a higher-precedence source.
    bool set(ParamId id, ParamValue value, ParamSource from);
    // Takes every value and source of `next` (a freshly composed set, see ParamLayers); the revision
    // moves on only when a value changed, so systems rebuild nothing for a no-op reload.
    void replace_with(const Params& next);
    std::uint64_t revision() const { return revision_; }

private:
    static std::size_t index(ParamId id) { return static_cast<std::size_t>(id); }
    std::array<ParamValue, param_count> values_;
    std::array<ParamSource, param_count> sources_{};
    std::uint64_t revision_ = 1;
};

}  // namespace puddle::params
