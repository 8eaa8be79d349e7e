#pragma once
// Display power: turns display.power (a schedule's display = "off", a knob's toggle, --set, a remote
// command) into the output going off and on.
//   input:   display power   when display.power changed: kms switches the connector's DPMS property
//                            (Display::set_power); window and headless, which have no output to switch,
//                            clear the frame to black and present it once (logged); with display.cec on,
//                            the TV is sent <Standby>, or <Image View On> and <Active Source>, on a worker
//                            thread (the CEC calls block for up to a second); a TV that does not answer
//                            is a warning
//   present: sleep while off the frame loop sleeps off_frame_sleep per frame (the watchdog is still
//                            pinged, config reloads and knobs still apply)
// Register it after the systems that change Params (live tuning, the schedule) and before the puddle's.

#include <memory>
#include <string>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "platform/cec_adapter.hpp"
#include "platform/display.hpp"
#include "systems/common/output_power.hpp"
#include "util/background_job.hpp"

namespace puddle::systems {

// How long a frame sleeps while the output is off: ten frames a second keep the watchdog, reloads and
// knobs going for next to no CPU.
inline constexpr double off_frame_sleep_seconds = 0.1;

// What one CEC exchange came to: a line for the log, at warning level when the TV did not answer or the
// adapter failed.
struct CecOutcome {
    bool warning = false;
    std::string message;
};

// Resource.
struct DisplayPower {
    platform::CecIo* cec_io = &platform::system_cec_io();  // tests give a fake adapter
    std::unique_ptr<BackgroundJob<CecOutcome>> cec = std::make_unique<BackgroundJob<CecOutcome>>();
};

void display_power_system(platform::Display& display, gpu::Device& device, const params::Params& params,
                          OutputPower& power, DisplayPower& state);
void sleep_while_off_system(const OutputPower& power);

// Inserts DisplayPower and registers the two systems. The output starts on; the first frame applies
// display.power (a start inside a night-off window switches the output off at once).
Result<void> add_display_power(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
