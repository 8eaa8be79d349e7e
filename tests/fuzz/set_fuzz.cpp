// Fuzz target: `--set name=value` (parse_assignment). An accepted assignment names a declared parameter
// and holds a value that passes the registry's range check; everything else is an error naming the flag.

#include <string_view>

#include "fuzz_support.hpp"
#include "params/config_loader.hpp"

using namespace puddle;
using namespace puddle::params;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto entry = parse_assignment(text);
    if (!entry) {
        PUDDLE_FUZZ_CHECK(!entry.error().message.empty(), "an error without a message");
        return 0;
    }
    const ParamDecl& d = decl(entry->id);
    PUDDLE_FUZZ_CHECK(text.starts_with(d.name), "'%.*s' was taken as %s", static_cast<int>(size),
                      reinterpret_cast<const char*>(data), std::string(d.name).c_str());
    const auto valid = validate(d, entry->value);
    PUDDLE_FUZZ_CHECK(valid.ok(), "accepted out of range: %s", valid.error().message.c_str());
    return 0;
}
