#include "bench/bench_baseline.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

namespace puddle::bench {

namespace {

// Ratios drift with the machine's load, so they get a generous margin; the shader cost is exact.
constexpr double ratio_tolerance = 1.25;

}  // namespace

Figures read_baseline(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    Figures f;
    const std::regex entry(R"re("([^"]+)"\s*:\s*([-+0-9.eE]+))re");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), entry); it != std::sregex_iterator(); ++it)
        f[(*it)[1].str()] = std::stod((*it)[2].str());
    return f;
}

bool write_baseline(const std::string& path, Figures f) {
    for (const auto& [name, value] : read_baseline(path)) f.emplace(name, value);  // keeps what was not run
    std::ofstream out(path);
    out << "{\n  \"_about\": \"puddle-bench --update-baseline: ratios to the floor pass (or to raymarch) and "
           "the "
           "render shader's estimated cost; lower is better\",\n";
    std::size_t k = 0;
    for (const auto& [name, value] : f)
        out << fmt::format("  \"{}\": {:.3f}{}\n", name, value, ++k < f.size() ? "," : "");
    out << "}\n";
    return static_cast<bool>(out);
}

bool check_baseline(const Figures& now, const Figures& baseline, const std::string& path) {
    std::printf("\nAgainst the baseline %s (ratios, lower is better; flagged over %.0f%%)\n", path.c_str(),
                (ratio_tolerance - 1) * 100);
    bool regressed = false;
    for (const auto& [name, value] : now) {
        const auto base = baseline.find(name);
        if (base == baseline.end()) {
            std::printf("  %-36s %9.2f  (no baseline)\n", name.c_str(), value);
            continue;
        }
        const bool exact = name.starts_with("shader/");
        const bool bad = exact ? value > base->second + 0.5 : value > base->second * ratio_tolerance;
        regressed = regressed || (bad && exact);  // timings only warn: one noisy run must not fail a build
        std::printf("  %-36s %9.2f  baseline %9.2f  %s\n", name.c_str(), value, base->second,
                    bad                                      ? "REGRESSION"
                    : value < base->second / ratio_tolerance ? "better"
                                                             : "ok");
    }
    return regressed;
}

}  // namespace puddle::bench
