#include "app/wall_screenshot.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>

#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/clock/wall_steps.hpp"

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
    const std::int64_t now = wall->now_ns();
    const double ahead = at_seconds - static_cast<double>(now) * 1e-9;
    if (!std::isfinite(at_seconds) || ahead <= 0 || ahead > 86400)
        return make_error(ExitCode::Config,
                          "--screenshot-at {:.3f}: {}: give a time from now to a day ahead in seconds since "
                          "the Unix epoch, e.g. $(date -d '+1 min' +%s)",
                          at_seconds,
                          !std::isfinite(ahead) ? "not a time"
                          : ahead <= 0          ? fmt::format("that time is {:.1f} s in the past", -ahead)
                                                : fmt::format("that time is {:.0f} s ahead", ahead));
    const WallScreenshot shot{.at_ns = std::llround(at_seconds * 1e9),
                              .step = systems::step_at(std::llround(at_seconds * 1e9),
                                                       params.get<ParamId::wave_steps_per_second>())};
    steps->stop_step = shot.step;
    spdlog::info("wall: will write wave step {} in {:.1f} s", shot.step,
                 static_cast<double>(shot.at_ns - now) * 1e-9);
    return shot;
}

Result<bool> wall_screenshot_due(ecs::World& world, const WallScreenshot& shot) {
    if (static_cast<std::int64_t>(world.resource<systems::FrameClock>().step_index) >= shot.step) return true;
    if (world.resource<systems::WallClock>().now_ns() < shot.at_ns + 5 * systems::ns_per_second) return false;
    return make_error(
        ExitCode::Runtime,
        "wall: wave step {} not reached 5 s after --screenshot-at: this screen warms up too "
        "slowly (or its output is off); give a time further ahead, e.g. $(date -d '+1 min' +%s)",
        shot.step);
}

}  // namespace puddle::app
