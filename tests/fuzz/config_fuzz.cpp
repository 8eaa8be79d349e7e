// Fuzz target: the TOML config and preset loader (parse_config), as a config file or a preset reaches it.
// Whatever the text, parsing returns a Config or an error; every entry it accepts passes the registry's
// own check again, applies to a parameter set, and a named preset resolves or is refused.

#include <string_view>

#include "fuzz_support.hpp"
#include "params/config_loader.hpp"
#include "params/presets.hpp"

using namespace puddle;
using namespace puddle::params;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Presets presets = Presets::load({});
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto config = parse_config(text, "fuzz.toml");
    if (!config) {
        PUDDLE_FUZZ_CHECK(!config.error().message.empty(), "an error without a message");
        return 0;
    }
    for (const ConfigEntry& e : config->entries) {
        const auto valid = validate(decl(e.id), e.value);
        PUDDLE_FUZZ_CHECK(valid.ok(), "accepted %s: %s", std::string(decl(e.id).name).c_str(),
                          valid.error().message.c_str());
        PUDDLE_FUZZ_CHECK(e.line >= 1, "entry %s without a line", std::string(decl(e.id).name).c_str());
    }
    Params params;
    apply_config(*config, params);
    if (config->preset && presets.contains(*config->preset)) {
        auto preset = presets.get(*config->preset);
        PUDDLE_FUZZ_CHECK(preset.ok(), "built-in preset %s does not load", config->preset->c_str());
    }
    for (const KnobSpec& k : config->knobs) (void)k.describe();
    return 0;
}
