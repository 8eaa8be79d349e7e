// Fuzz target: the knob state file loader (StateStore::load), reading the file from disk as at start-up.
// A readable file gives a state holding only parameters; anything else is moved aside with a warning,
// never an exception or a crash, and the bad file no longer sits where the next start would read it.

#include <filesystem>

#include "fuzz_support.hpp"
#include "params/state_store.hpp"

using namespace puddle;
using namespace puddle::params;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace fs = std::filesystem;
    const std::string path = fuzz::write_scratch_file("state.toml", {data, size});
    const StateStore store(path);
    const StateStore::Loaded loaded = store.load();
    std::error_code ec;
    if (loaded.state) {
        PUDDLE_FUZZ_CHECK(loaded.state->knobs.empty(), "a state with [[knob]] tables was taken");
        for (const ConfigEntry& e : loaded.state->entries)
            PUDDLE_FUZZ_CHECK(validate(decl(e.id), e.value).ok(), "accepted an invalid %s",
                              std::string(decl(e.id).name).c_str());
    } else {
        PUDDLE_FUZZ_CHECK(!loaded.warning.empty(), "a file was refused without a warning");
        PUDDLE_FUZZ_CHECK(!fs::exists(path, ec), "a refused state file stayed in place");
    }
    // Whatever the loader set aside belongs to this input only.
    for (const auto& entry : fs::directory_iterator(fuzz::scratch_dir(), ec)) fs::remove(entry.path(), ec);
    return 0;
}
