// Fuzz target: the knob state file loader (StateStore::load), reading the file from disk as at start-up.
// Loading changes nothing on disk; what it keeps holds only valid parameter values, and every key it
// drops (or the reason nothing could be read) is reported. A file with problems is then set aside as the
// program does, and the copy must hold the original bytes.

#include <filesystem>
#include <fstream>
#include <iterator>

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
    StateStore store(path);  // set_aside() records a failure
    const StateStore::Loaded loaded = store.load();
    std::error_code ec;
    PUDDLE_FUZZ_CHECK(fs::exists(path, ec) && fs::file_size(path, ec) == size, "load() changed the file");
    if (loaded.state) {
        PUDDLE_FUZZ_CHECK(loaded.state->knobs.empty(), "a state with [[knob]] tables was taken");
        for (const ConfigEntry& e : loaded.state->entries)
            PUDDLE_FUZZ_CHECK(validate(decl(e.id), e.value).ok(), "kept an invalid %s",
                              std::string(decl(e.id).name).c_str());
    } else {
        PUDDLE_FUZZ_CHECK(!loaded.problems.empty(), "nothing was read and no reason was given");
    }
    if (!loaded.problems.empty()) {
        auto copy = store.set_aside();
        PUDDLE_FUZZ_CHECK(copy.ok(), "set_aside failed: %s", copy.error().message.c_str());
        std::ifstream in(*copy, std::ios::binary);
        const std::string kept{std::istreambuf_iterator<char>(in), {}};
        PUDDLE_FUZZ_CHECK(kept.size() == size && std::equal(kept.begin(), kept.end(), data, data + size,
                                                            [](char a, std::uint8_t b) {
                                                                return static_cast<std::uint8_t>(a) == b;
                                                            }),
                          "the set-aside copy differs from the file");
    }
    // Whatever was set aside belongs to this input only.
    for (const auto& entry : fs::directory_iterator(fuzz::scratch_dir(), ec)) fs::remove(entry.path(), ec);
    return 0;
}
