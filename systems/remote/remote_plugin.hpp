#pragma once
// Remote control over MQTT as systems; the client, its topics and Home Assistant discovery
// are src/remote's, this file wires them to the frame:
//   input:   remote commands  takes what the network thread received (never waits for it) and asks
//                             live tuning (its TuningInbox) for it: a parameter (source Remote, saved
//                             with the knob state), a preset, a command; a bad message (or a preset that
//                             does not load) is one warning and a reply on <prefix>/error, nothing
//                             asked; a retained command is never applied (one warning per topic)
//   present: remote publish   after the present: the screenshot of the frame just shown (read back by
//                             the capture system before it), the state when Params changed or after a
//                             (re)connect, health every remote.health_interval seconds, discovery
// The encoding of a screenshot (scaling, JPEG) runs on a worker thread.

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "remote/board_power.hpp"
#include "remote/mqtt_client.hpp"
#include "remote/remote_settings.hpp"
#include "systems/common/frame_stats.hpp"
#include "systems/display/display_plugin.hpp"
#include "systems/sky/camera_system.hpp"
#include "systems/tuning/live_tuning.hpp"
#include "util/background_job.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// Resource.
struct RemoteControl {
    remote::RemoteSettings settings;
    std::unique_ptr<remote::MqttClient> client;
    // remote.enabled = false with remote.host set: clear the discovery configs, nothing else.
    bool clear_only = false;
    std::vector<remote::Inbound> inbox;  // reserved once: draining allocates nothing
    std::uint64_t connections_seen = 0;
    std::unique_ptr<params::Params> published;  // what the state topics hold; null: publish everything
    std::string published_preset;
    bool preset_published = false;
    bool discovery_due = false;
    double started = 0;
    FrameStats stats;
    // A Raspberry Pi's under-voltage and throttling (remote/board_power.hpp), polled once a second and
    // reported with each health message; said in the log when it starts and when it ends.
    remote::BoardPowerWatch board_power;
    double next_power_poll = 0;
    remote::BoardPower last_power;
    const systems::CameraFeed* camera = nullptr;  // for the dropped-frame count, when the puddle has one
    bool screenshot_wanted = false;               // a capture was asked for and not yet taken
    // Command topics a retained message was ignored on, said once each (the broker replays it at every
    // reconnect).
    std::set<std::string> retained_reported;
    std::unique_ptr<BackgroundJob<std::string>> encoder = std::make_unique<BackgroundJob<std::string>>();

    explicit RemoteControl(remote::RemoteSettings s)
        : settings(std::move(s)), stats(settings.health_interval_s) {}
    // Logs `message` (warning) and replies on <prefix>/error: {"topic": ..., "error": ...}.
    void reply_error(const std::string& topic, const std::string& message);
};

void remote_commands_system(RemoteControl& remote, const systems::LiveTuning& tuning,
                            systems::TuningInbox& inbox, systems::FrameCapture& capture);
void remote_publish_system(RemoteControl& remote, const params::Params& params,
                           const systems::LiveTuning& tuning, systems::FrameCapture& capture);

// Needs Params and LiveTuning in the world (and the puddle's CameraFeed, when there is one). With
// remote.enabled it starts the client and registers the systems above; with remote.enabled = false and
// remote.host set, it connects only to clear this screen's discovery configs; otherwise it does nothing.
// Errors: remote_settings()'s (a world-readable password file...), exit code 2.
Result<void> add_remote_plugin(ecs::World& world, ecs::Schedule& schedule);

}  // namespace puddle::systems
