#pragma once
// The health message, published every remote.health_interval seconds on <prefix>/health (retained):
// {"fps": 59.9, "frame_ms_p95": 17.1, "cpu_ms_per_frame": 4.2, "rss_mb": 88.5, "uptime_s": 3600,
//  "camera_dropped_frames": 0, "soc_temperature_c": 51.2, "undervoltage": false, "throttled": false};
// soc_temperature_c only where /sys/class/thermal has a zone, undervoltage and throttled only on a
// Raspberry Pi that reports them (remote/board_power.hpp). Home Assistant's sensors read it with value
// templates (discovery.hpp).

#include <optional>
#include <string>

namespace puddle::remote {

struct Health {
    double fps = 0;
    double frame_ms_p95 = 0;
    double cpu_ms_per_frame = 0;
    double rss_mb = 0;
    double uptime_s = 0;
    unsigned long long camera_dropped_frames = 0;
    std::optional<double> soc_temperature_c;
    // A Raspberry Pi's supply and throttling since the last health message (remote/board_power.hpp); none
    // on boards that do not report them.
    std::optional<bool> undervoltage;
    std::optional<bool> throttled;
};

std::string health_document(const Health& h);

// The first thermal zone's temperature in degrees Celsius (its `temp` file holds millidegrees), read
// under `thermal_dir` (/sys/class/thermal); none when there is no zone or it cannot be read.
std::optional<double> soc_temperature_c(const std::string& thermal_dir = "/sys/class/thermal");

// The health fields as Home Assistant sensors: key in the document, name, unit, device class ("" none).
struct HealthField {
    const char* key;
    const char* name;
    const char* unit;
    const char* device_class;
};
inline constexpr HealthField health_fields[] = {
    {"fps", "Frame rate", "fps", ""},
    {"frame_ms_p95", "Frame time p95", "ms", "duration"},
    {"cpu_ms_per_frame", "CPU per frame", "ms", "duration"},
    {"rss_mb", "Resident memory", "MB", "data_size"},
    {"uptime_s", "Uptime", "s", "duration"},
    {"camera_dropped_frames", "Dropped camera frames", "", ""},
    {"soc_temperature_c", "SoC temperature", "°C", "temperature"},
};
// The board's power flags as Home Assistant binary sensors (device class "problem": on means trouble).
inline constexpr HealthField health_problem_fields[] = {
    {"undervoltage", "Under-voltage", "", "problem"},
    {"throttled", "Throttled", "", "problem"},
};

}  // namespace puddle::remote
