#include "systems/display/display_power.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <thread>

namespace puddle::systems {

namespace {

constexpr std::string_view cec_osd_name = "Puddle";

// On the CEC worker thread: one exchange with the TV through a freshly opened adapter.
CecOutcome switch_tv(platform::CecIo& io, const std::string& path, bool on) {
    auto adapter = platform::CecAdapter::open(io, path, cec_osd_name);
    if (!adapter)
        return {true, fmt::format("{} (the TV stays as it is; DPMS still applies)", adapter.error().message)};
    const char* what = on ? "<Image View On> and <Active Source>" : "<Standby>";
    auto delivery = on ? adapter->wake_tv() : adapter->standby_tv();
    if (!delivery) return {true, fmt::format("{} (the TV stays as it is)", delivery.error().message)};
    if (*delivery == platform::CecDelivery::no_answer)
        return {true, fmt::format("cec: {}: {} sent, the TV did not answer (switched off at the wall, "
                                  "unplugged, or CEC turned off in its menu)",
                                  path, what)};
    return {false, fmt::format("cec: {}: {} acknowledged by the TV", path, what)};
}

void apply_power(platform::Display& display, gpu::Device& device, const params::Params& params,
                 OutputPower& power, DisplayPower& state, bool on) {
    power.on = on;
    power.black_frame_pending = false;
    if (display.switches_output_power()) {
        if (auto r = display.set_power(on); !r)  // logged by the backend when it works
            spdlog::error("{} (the picture stays {})", r.error().message, on ? "off" : "on");
    } else if (!on) {
        // No output to switch: one black frame, presented by the present stage.
        auto pass = device.begin_pass({.label = "display off",
                                       .target = display.frame_target(),
                                       .load = gpu::LoadOp::Clear,
                                       .clear = {0, 0, 0, 1}});
        pass.end();
        power.black_frame_pending = true;
        spdlog::info("display: off: {} has no output to switch off; one black frame shown, no more drawn",
                     platform::backend_name(display.kind()));
    } else {
        spdlog::info("display: on: drawing again");
    }
    if (params.get<params::ParamId::display_cec>() && state.cec)
        state.cec->submit([io = state.cec_io, path = params.get<params::ParamId::display_cec_device>(),
                           on](std::stop_token) { return switch_tv(*io, path, on); });
}

}  // namespace

void display_power_system(platform::Display& display, gpu::Device& device, const params::Params& params,
                          OutputPower& power, DisplayPower& state) {
    if (auto outcome = state.cec ? state.cec->take() : std::nullopt) {
        if (outcome->warning)
            spdlog::warn("{}", outcome->message);
        else
            spdlog::info("{}", outcome->message);
    }
    const bool on = params.get<params::ParamId::display_power>();
    if (on != power.on) apply_power(display, device, params, power, state, on);
}

void sleep_while_off_system(const OutputPower& power) {
    if (power.on) return;
    std::this_thread::sleep_for(std::chrono::duration<double>(off_frame_sleep_seconds));
}

Result<void> add_display_power(ecs::World& world, ecs::Schedule& schedule) {
    world.insert_resource<DisplayPower>();
    schedule.add(ecs::Stage::Input, "display power", display_power_system);
    schedule.add(ecs::Stage::Present, "sleep while off", sleep_while_off_system);
    return {};
}

}  // namespace puddle::systems
