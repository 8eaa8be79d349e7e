#pragma once
// Rain on a window at night (scene.kind = window): one fullscreen pass in screen space (window.frag).
// The eye is focused on the glass, so the city behind it is out of focus, its lights bokeh discs; on the
// glass, still beads that renew over minutes, and drops that run down in stick-slip surges, each in its
// own column, wiping a trail that new beads refill. A bead is a lens that shows the city upside down and
// in focus. Sizes are in metres of glass (window.view_height); docs/techniques.md ("Rain on a window")
// gives the figures and their sources.
//
// Time reaches the shader only through WindowTime, computed here in double (render/shader_phase.hpp):
// the beads' life as its whole count and fraction, each column's run as its repeat number and age, and
// the cars' drift as whole lattice cells and a fraction, so the window is continuous however long it runs.

#include <array>
#include <cstdint>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/fullscreen_pass.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/output_power.hpp"

namespace puddle::systems {

inline constexpr int window_max_streams = 32;  // window.streams' maximum
// How far the glass's run of a column reaches beyond the view: a drop starts above the top edge and
// leaves below the bottom one (metres: the largest running drop's radius, with room).
inline constexpr double window_run_margin = 0.01;
// Cars drift this many of their lattice cells (0.11 view heights) a second.
inline constexpr double window_traffic_cells_per_second = 0.9;

// A run that rests (lighter rain leaves some columns dry for a run) is given this age: its drop is far
// below the view and its trail long refilled.
inline constexpr double window_resting_age = 1.0e4;

// How wet the glass is at a rain rate (mm/h), 0..1: 1 - exp(-rate / 2.5 mm/h); about 0.7 at the default
// 3 mm/h, under 0.2 in drizzle. It scales the still beads' cover, and how many runs go.
double window_wetness(double rate_mm_h);

// Everything window.frag needs of the time `seconds`.
struct WindowTime {
    float bead_phase = 0;     // fraction of window.bead_life, in [0, 1)
    int bead_cycle = 0;       // whole bead lives since the start (the bits of a uint)
    float traffic_shift = 0;  // fraction of a lattice cell
    int traffic_cells = 0;    // whole cells (the bits of a uint)
    float wetness = 0;        // window_wetness of the rain rate now (rain_rate_at)
    // Seconds since the column's drop set off, or window_resting_age while the column rests this run.
    std::array<float, window_max_streams> stream_age{};
    std::array<int, window_max_streams> stream_repeat{};  // which run (the bits of a uint)
};

// Seconds until beads fill a trail again and its wet edges have dried (window.frag's TRAIL_REFILL).
inline constexpr double window_trail_refill = 6.0;

// Column i's runs repeat every this many seconds: 1.8 to 3.2 times the run at window.slide_speed (a drop
// runs at 0.6 to 1.5 times it, so the slowest leaves the view before its column's next run) and the
// trail's refill after it, so a new run never wipes away an old trail at once; seeded by rain.seed, so
// each column keeps its own rhythm.
double window_stream_period(const params::Params& params, int column);

WindowTime window_time(const params::Params& params, double seconds);

// Resource.
struct WindowRenderer {
    FullscreenPass pass;
    WindowRenderer();
};

void window_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                   WindowRenderer& window, const RenderTarget& target);

// The window's plugin: its resource, its entry in Looks (scene.kind = window) and its render system.
void add_window_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
