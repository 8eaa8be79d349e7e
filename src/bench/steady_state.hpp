#pragma once
// The wave field a wall shows all day, for puddle-bench to time: rain on a calm start roughens the water
// for a few hundred steps, and a rough surface costs more to render (the refine step and the reflected
// directions spread, so texture reads lose their locality): 46 to 56 ms against 42 ms at 1080p on one
// llvmpipe machine. The benchmark times the steady state; the calm start stays a labelled extra.
//
// Why this is steady: each step keeps wave.damping (0.985) of the field and the drops add a bounded
// impulse per step, so the roughness approaches the level where the two balance with a time constant of
// 1 / (1 - damping), about 67 steps; after five of them (about 330 steps) it is within 1% of that level.
// Rather than trust the arithmetic, the warm-up measures the field's RMS slope once per simulated second
// and stops when it has set no new high (by more than steady_growth) for steady_seconds in a row.

#include <vector>

#include "app/engine.hpp"

namespace puddle::bench {

inline constexpr int steady_check_steps = 60;     // one simulated second at the default 60 steps/s
inline constexpr double steady_growth = 0.02;     // a new high by less than 2% is no longer growth
inline constexpr int steady_seconds = 3;          // this many checks in a row without growth
inline constexpr int steady_max_steps = 60 * 60;  // a field that never settles is timed after a minute

// The root mean square of the height differences between neighbouring texels (x and z), in height units
// per texel, of a field read by WaveField::read_heights (height, previous height per texel, rows by z).
// 0 for a flat field or one smaller than 2x2.
double rms_slope(const std::vector<float>& heights, int resolution);

struct Warmup {
    int steps = 0;            // simulate steps run
    double calm_slope = 0;    // RMS slope before them
    double steady_slope = 0;  // and after
    bool steady = false;      // false: steady_max_steps ran out while it still grew
};

// Runs the engine's simulate stage (drops and wave, no render) until the field's RMS slope stops growing.
Warmup warm_to_steady_state(app::Engine& engine);

}  // namespace puddle::bench
