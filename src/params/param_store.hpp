#pragma once
// Params: the current value of every declared parameter and where it came from. A World resource that
// the input stage writes (config, --set, later knobs) and systems read. `revision` changes whenever a
// value does, so a system can rebuild what depends on it without comparing every value each frame.

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <type_traits>
#include <variant>

#include "params/param_types.hpp"
#include "params/registry.hpp"

namespace puddle::params {

// Lowest to highest precedence; a value from a higher source is never overwritten by a lower one.
// Schedule: the config's [[schedule]] entries active now. Remote (MQTT) shares the knob level: the last
// of the two to set a parameter holds it.
enum class ParamSource : std::uint8_t { Default, Preset, Config, Schedule, Knob, Remote, CommandLine };
std::string_view source_name(ParamSource s);

class Params {
public:
    Params();  // every value at its declared default

    // The value, as its declared type (params/param_types.hpp): bool, int, float, glm::vec3, the
    // parameter's enum, or const std::string& for a path. Never throws: the type comes from the same
    // declaration as the stored value.
    template <ParamId id>
    decltype(auto) get() const {
        using T = ParamType<id>;
        if constexpr (std::is_enum_v<T>)
            return static_cast<T>(choices_[index(id)]);
        else if constexpr (std::is_same_v<T, std::string>)
            return static_cast<const std::string&>(*std::get_if<T>(&values_[index(id)]));
        else
            return T(*std::get_if<T>(&values_[index(id)]));
    }
    // For code over every parameter (docs, uniforms, state): the value as declared data, and an enum's
    // choice as its index in decl(id).choices.
    const ParamValue& at(ParamId id) const { return values_[index(id)]; }
    int choice_index(ParamId id) const { return choices_[index(id)]; }
    ParamSource source(ParamId id) const { return sources_[index(id)]; }

    // Sets a value that was validated against its declaration. Returns false (and changes nothing) when
    // the current value comes from a higher-precedence source.
    // A value of another kind than the declaration's, or an enum text that is no choice, is refused too
    // (false): read back through get<>(), it would be a wrong type.
    bool set(ParamId id, ParamValue value, ParamSource from);
    // The typed set, for code (tests, the benchmark): a wrong type or an unknown choice does not compile.
    template <ParamId id>
    bool set(ParamType<id> value, ParamSource from) {
        if constexpr (std::is_enum_v<ParamType<id>>)
            return set(id, ParamValue(std::string(choice_name(value))), from);
        else
            return set(id, ParamValue(std::move(value)), from);
    }
    // Takes every value and source of `next` (a freshly composed set, see ParamLayers); the revision
    // moves on only when a value changed, so systems rebuild nothing for a no-op reload.
    void replace_with(const Params& next);
    std::uint64_t revision() const { return revision_; }

private:
    static std::size_t index(ParamId id) { return static_cast<std::size_t>(id); }
    void store(std::size_t k, ParamValue value);
    std::array<ParamValue, param_count> values_;
    std::array<ParamSource, param_count> sources_{};
    std::array<std::uint8_t, param_count> choices_{};  // an enum's value as its index, kept with values_
    std::uint64_t revision_ = 1;
};

}  // namespace puddle::params
