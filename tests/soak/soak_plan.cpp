#include "soak/soak_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numeric>

namespace puddle::soak {

namespace {

constexpr std::array<Look, looks_per_cycle> looks{{
    {"puddle", "pulse", false},
    {"puddle", "analytic", false},
    {"puddle", "grid", false},
    {"ocean", "pulse", false},
    {"street", "pulse", true},
    {"puddle", "pulse", true},
}};

}  // namespace

long SoakPlan::warmup_frames() const {
    // Looks repeat every 12 reloads and field sizes every 8: every pairing of the two recurs every 24.
    // The camera's unplug period crosses them: every look and field size has been drawn with the
    // camera's cube and with the sky's after lcm(24 reloads, unplug_every) frames (21 600 by default).
    const long pairings = std::lcm(looks_per_cycle * 2, 8L) * reload_every;
    const long with_camera_states = unplugs ? std::lcm(pairings, unplug_every) : pairings;
    const long needed = std::max(2 * pairings, with_camera_states);
    return (needed + check_every - 1) / check_every * check_every;
}

Look SoakPlan::look_for_reload(long k) const {
    if (!look_switches) return looks[0];
    return looks[static_cast<std::size_t>((k / 2) % looks_per_cycle)];
}

int SoakPlan::wave_resolution_for_reload(long k) const {
    if (!field_rebuilds) return 64;
    return (k / 4) % 2 ? 96 : 64;
}

int seed_for_reload(long k) {
    return static_cast<int>(k % 2'000'000'000) + 1;
}

std::string SoakPlan::config(long k, const std::string& camera_folder) const {
    const Look look = look_for_reload(k);
    return fmt::format(
        R"(# puddle-soak: reload {k}
[rain]
seed = {seed}
drop_count = {drops}
intensity = {intensity:.2f}

[wave]
resolution = {resolution}

[scene]
kind = "{scene}"

[drops]
model = "{model}"

[overlay]
rain = {overlay}

[look]
vignette = {vignette:.2f}

[environment]
source = "camera"
camera_device = "mock:{camera}"
camera_fps = 2.0
)",
        fmt::arg("k", k), fmt::arg("seed", seed_for_reload(k)), fmt::arg("drops", 8 + (k % 4) * 8),
        fmt::arg("intensity", 0.2 + 0.1 * static_cast<double>(k % 5)),
        fmt::arg("resolution", wave_resolution_for_reload(k)), fmt::arg("scene", look.scene),
        fmt::arg("model", look.drops), fmt::arg("overlay", look.rain_overlay),
        fmt::arg("vignette", 0.3 + 0.1 * static_cast<double>(k % 7)), fmt::arg("camera", camera_folder));
}

}  // namespace puddle::soak
