#pragma once
// What the soak program (soak.cpp) does and when: the schedule in frames, and the config file it writes
// at each live reload. Frames advance a fixed 1/60 s of simulated time, so the schedule reads in seconds
// of simulated time as well.

#include <string>

namespace puddle::soak {

// The look a reload asks for: scene.kind, drops.model and overlay.rain.
struct Look {
    const char* scene;
    const char* drops;
    bool rain_overlay;
};

struct SoakPlan {
    long frames = 1'000'000;
    double dt = 1.0 / 60.0;    // simulated seconds per frame (the headless binary's fixed step)
    long reload_every = 180;   // 3 s: rewrite the config; every second reload also switches the look
    long unplug_every = 1200;  // 20 s: the mock camera's folder is renamed away...
    long unplug_at = 600;      // ...this far into each period...
    long replug_after = 180;   // ...and back 3 s later (the feed retries every second)
    long check_every = 2000;   // GL errors, height field, resident memory and open fds
    // What runs (`puddle-soak --without ...` turns parts off, to find which one makes memory grow).
    bool reloads = true, look_switches = true, field_rebuilds = true, unplugs = true;
    // Baseline for memory and fds: the first check after every look at every field size has run both
    // with the camera streaming and unplugged (lcm of 24 reloads and the unplug period: 21 600 frames;
    // at least the pairings of look and field size twice, 8640 frames, without unplugs). Memory climbs
    // until then as llvmpipe compiles a shader variant for each new combination of state it meets:
    // with a baseline at 9000 frames, a 10^6-frame run rose 600 to 700 KiB by frame 22 000 and then
    // stayed there, and short runs sometimes failed at +1.4 MiB.
    long warmup_frames() const;

    // The look reload k asks for: six looks, each held for two reloads (the first only, without switches).
    Look look_for_reload(long k) const;
    // wave.resolution for reload k: 64 and 96 alternate every four reloads (a field rebuild each time).
    int wave_resolution_for_reload(long k) const;
    // The config file of reload k (k = 0: the one at start-up), reflecting the mock camera `camera_folder`.
    std::string config(long k, const std::string& camera_folder) const;
};

inline constexpr long looks_per_cycle = 6;
// rain.seed for reload k: a marker that tells the soak the reload was applied.
int seed_for_reload(long k);

}  // namespace puddle::soak
