#pragma once
// Rain streaks (REFERENCE.md section 3's four parallax layers) blended over whatever scene was drawn,
// when overlay.rain = true. Runs after the scene passes, before present. Each streak is a quad of its own
// (rain_streaks.vert), so the pass shades the pixels the rain covers, not the whole view.
//
// A layer's streaks fall at its own speed times overlay.rain_speed, in cells per second, and the fall
// repeats every cell: the shader gets each layer's fall modulo 1, computed here in double
// (render/shader_phase.hpp), so the rain is continuous at any uptime.

#include <array>
#include <glm/vec4.hpp>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/common/fullscreen_pass.hpp"
#include "systems/common/output_power.hpp"
#include "systems/common/shown_look.hpp"

namespace puddle::systems {

// Fall speeds of the four streak layers (shaders_gles/rain_streak_cells.glsl), far to near, in cells per
// second.
inline constexpr std::array<double, 4> rain_layer_speeds{1.8, 2.5, 3.2, 3.8};
// Their scales (LAYERS[i].x there): a layer has 1.5 scale cells across the view and 0.15 scale up it.
inline constexpr std::array<int, 4> rain_layer_scales{80, 50, 30, 18};

// The quads rain_streaks.vert draws: two per cell of every layer (a streak and the part of it that
// wrapped round the cell), most of them empty.
constexpr int rain_streak_quads() {
    int quads = 0;
    for (const int scale : rain_layer_scales) quads += 2 * ((3 * scale + 1) / 2) * ((3 * scale + 19) / 20);
    return quads;
}

// Each layer's fall at `seconds` for overlay.rain_speed `speed`: cells modulo 1.
glm::vec4 rain_layer_falls(double seconds, double speed);

// How many streaks fall, as a factor of overlay.rain_density: under wave.model = capillary the rain's
// current rate (rain.rate with its drift, systems/water/rain_rate.hpp) over 3 mm/h, at most 2.5, so the
// streaks thin out in a lull and thicken in a shower with the rings; 1 under the reference's model.
double streak_density_factor(const params::Params& params, double sim_time);

// Resource.
struct RainOverlay {
    FullscreenPass pass;
    RainOverlay();
};

void rain_overlay_system(gpu::Device& device, const params::Params& params, const FrameClock& clock,
                         RainOverlay& rain, const RenderTarget& target);

// The rain overlay's plugin: its resource and its render system (over whichever look is shown, while
// overlay.rain is on). Builds its pipeline at once when overlay.rain is on at start-up (errors: a shader
// that does not build); switched on later, it is built off the frame thread and drawn once ready.
Result<void> add_rain_overlay_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
