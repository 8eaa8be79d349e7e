#include "remote/health.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "remote/state_json.hpp"

namespace puddle::remote {

namespace {

// A JSON number with `decimals` digits after the point (59.9, not 59.900000000000006).
nlohmann::json rounded(double v, int decimals) {
    return nlohmann::json::parse(fmt::format("{:.{}f}", std::isfinite(v) ? v : 0.0, decimals));
}

}  // namespace

std::string health_document(const Health& h) {
    nlohmann::json doc = {
        {"fps", rounded(h.fps, 1)},
        {"frame_ms_p95", rounded(h.frame_ms_p95, 2)},
        {"cpu_ms_per_frame", rounded(h.cpu_ms_per_frame, 2)},
        {"rss_mb", rounded(h.rss_mb, 1)},
        {"uptime_s", std::floor(h.uptime_s)},
        {"camera_dropped_frames", h.camera_dropped_frames},
    };
    if (h.soc_temperature_c) doc["soc_temperature_c"] = rounded(*h.soc_temperature_c, 1);
    if (h.undervoltage) doc["undervoltage"] = *h.undervoltage;
    if (h.throttled) doc["throttled"] = *h.throttled;
    return dump_json(doc);
}

std::optional<double> soc_temperature_c(const std::string& thermal_dir) {
    std::ifstream in(thermal_dir + "/thermal_zone0/temp");
    long millidegrees = 0;
    if (!(in >> millidegrees)) return std::nullopt;
    return static_cast<double>(millidegrees) / 1000.0;
}

}  // namespace puddle::remote
