#include "app/wall_screenshot.hpp"

#include <spdlog/spdlog.h>

#include <cmath>

#include "params/param_store.hpp"
#include "systems/frame_clock.hpp"
#include "systems/wall_clock.hpp"
#include "systems/wall_steps.hpp"

namespace puddle::app {

using params::ParamId;

Result<WallScreenshot> arm_wall_screenshot(ecs::World& world, double at_seconds) {
    const params::Params& params = world.resource<params::Params>();
    if (params.get<ParamId::wall_clock>() != params::WallClockMode::realtime)
        return make_error(
            ExitCode::Config,
            "--screenshot-at needs wall.clock = \"realtime\" ([wall] clock = \"realtime\" in the "
            "config, or --set wall.clock=realtime): otherwise each screen counts time from its "
            "own start");
    auto* steps = world.try_resource<systems::WallSteps>();
    const auto* wall = world.try_resource<systems::WallClock>();
    if (!steps || !wall)
        return make_error(ExitCode::Config, "--screenshot-at: this engine has no wall clock");
    const WallScreenshot shot{.at_ns = std::llround(at_seconds * 1e9),
                              .step = systems::step_at(std::llround(at_seconds * 1e9),
                                                       params.get<ParamId::wave_steps_per_second>())};
    const std::int64_t now = wall->now_ns();
    if (shot.at_ns <= now)
        return make_error(ExitCode::Config, "--screenshot-at {:.3f}: that time is {:.1f} s in the past",
                          at_seconds, static_cast<double>(now - shot.at_ns) * 1e-9);
    steps->stop_step = shot.step;
    spdlog::info("wall: will write wave step {} in {:.1f} s", shot.step,
                 static_cast<double>(shot.at_ns - now) * 1e-9);
    return shot;
}

bool wall_screenshot_due(ecs::World& world, const WallScreenshot& shot) {
    if (static_cast<std::int64_t>(world.resource<systems::FrameClock>().step_index) >= shot.step) return true;
    if (world.resource<systems::WallClock>().now_ns() < shot.at_ns + 5 * systems::ns_per_second) return false;
    spdlog::warn(
        "wall: wave step {} not reached 5 s after its time (was the output off?): writing this frame",
        shot.step);
    return true;
}

}  // namespace puddle::app
