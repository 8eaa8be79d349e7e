#pragma once
// Shared by the libFuzzer targets in this folder: a scratch folder per process for the loaders that read
// files, and a check that stops the run (libFuzzer then saves the input) when an invariant breaks. Every
// target quietens spdlog: a warning per input would cost more than the input itself.

#include <spdlog/spdlog.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <span>
#include <string>
#include <string_view>

namespace puddle::fuzz {

// A folder of its own under $TMPDIR (or /tmp), made on first use and reused for every input; libFuzzer's
// -fork and -jobs modes start one process per job, so the pid keeps jobs apart.
inline const std::string& scratch_dir() {
    static const std::string dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/puddle-fuzz-XXXXXX";
        if (mkdtemp(pattern.data()) == nullptr) {
            std::perror("fuzz: mkdtemp");
            std::abort();
        }
        return pattern;
    }();
    return dir;
}

inline std::string write_scratch_file(std::string_view name, std::span<const std::uint8_t> bytes) {
    const std::string path = scratch_dir() + "/" + std::string(name);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return path;
}

// An invariant of Puddle's own code broke: say which, and abort so libFuzzer keeps the input.
#define PUDDLE_FUZZ_CHECK(condition, ...)                                                            \
    do {                                                                                             \
        if (!(condition)) {                                                                          \
            std::fprintf(stderr, "fuzz: %s:%d: check failed: %s: ", __FILE__, __LINE__, #condition); \
            std::fprintf(stderr, __VA_ARGS__);                                                       \
            std::fprintf(stderr, "\n");                                                              \
            std::abort();                                                                            \
        }                                                                                            \
    } while (0)

inline void quiet_logs() {
    spdlog::set_level(spdlog::level::off);
}

}  // namespace puddle::fuzz
