// Fuzz target: the `[[knob]]` table parser (parse_knob). The input is the body of one knob table; the
// target puts the header in front so the fuzzer spends its time on knob keys, not on finding the header.
// An accepted knob names its lines and, where it changes a parameter, a declared one.

#include <string>

#include "fuzz_support.hpp"
#include "params/knob_spec_parse.hpp"

using namespace puddle;
using namespace puddle::params;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text = "[[knob]]\n" + std::string(reinterpret_cast<const char*>(data), size);
    toml::table root;
    try {
        root = toml::parse(text, std::string_view("fuzz.toml"));
    } catch (const toml::parse_error&) {
        return 0;  // toml++'s own refusal; the config loader turns it into a message
    }
    const toml::array* knobs = root["knob"].as_array();
    if (knobs == nullptr) return 0;  // the body replaced the table with another value
    int index = 0;
    for (const toml::node& node : *knobs) {
        ++index;
        const toml::table* table = node.as_table();
        if (table == nullptr) continue;
        auto knob = parse_knob(*table, "fuzz.toml", index);
        if (!knob) {
            PUDDLE_FUZZ_CHECK(!knob.error().message.empty(), "an error without a message");
            continue;
        }
        PUDDLE_FUZZ_CHECK(!knob->line.empty(), "a knob without a line: %s", knob->describe().c_str());
        PUDDLE_FUZZ_CHECK(knob->kind != KnobKind::Encoder || !knob->line_b.empty(),
                          "an encoder without line B: %s", knob->describe().c_str());
        PUDDLE_FUZZ_CHECK(knob->debounce_ms >= 0, "negative debounce: %d", knob->debounce_ms);
    }
    return 0;
}
