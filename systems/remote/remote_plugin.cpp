#include "systems/remote/remote_plugin.hpp"

#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>

#include "remote/discovery.hpp"
#include "remote/health.hpp"
#include "remote/state_json.hpp"
#include "systems/remote/screenshot_jpeg.hpp"
#include "util/monotonic_clock.hpp"
#include "util/safe_quote.hpp"
#include "util/version.hpp"

namespace puddle::systems {

using params::ParamId;

namespace {

void publish_all(remote::MqttClient& client, std::vector<remote::Outbound> messages) {
    for (remote::Outbound& m : messages) client.publish(std::move(m.topic), std::move(m.payload), m.retain);
}

// A preset the remote asks for is checked here, so a name that does not load is answered on the error
// topic; live tuning switches to it.
Result<void> ask_for_preset(const systems::LiveTuning& t, systems::TuningInbox& inbox,
                            const std::string& name, std::optional<std::int64_t> apply_at_ns) {
    if (!name.empty())
        if (auto preset = t.layers.presets().get(name); !preset) return preset.error();
    inbox.push(systems::SelectPreset{.name = name, .source = "remote", .apply_at_ns = apply_at_ns});
    return {};
}

Result<void> apply(RemoteControl& r, const systems::LiveTuning& t, systems::TuningInbox& inbox,
                   systems::FrameCapture& capture, const remote::Request& request) {
    using remote::Command;
    if (const auto* set = std::get_if<remote::SetParam>(&request)) {
        inbox.push(
            systems::SetRemoteValue{.id = set->id, .value = set->value, .apply_at_ns = set->apply_at_ns});
        return {};
    }
    if (const auto* preset = std::get_if<remote::SelectPreset>(&request))
        return ask_for_preset(t, inbox, preset->name, preset->apply_at_ns);
    if (std::holds_alternative<remote::HomeAssistantOnline>(request)) {
        r.discovery_due = true;
        return {};
    }
    const auto* command = std::get_if<Command>(&request);
    if (!command) return {};
    switch (*command) {
        case Command::NextPreset:
        case Command::PreviousPreset:
            return ask_for_preset(
                t, inbox,
                t.layers.presets().step(t.layers.preset_name(), *command == Command::NextPreset ? 1 : -1),
                std::nullopt);
        case Command::Save:
            inbox.push(systems::SaveState{});
            return {};
        case Command::Screenshot:
            capture.requested = true;  // read back before the next present (systems::capture_system)
            r.screenshot_wanted = true;
            return {};
        case Command::Reload:
            inbox.push(systems::ReloadConfig{"remote"});
            return {};
    }
    return {};
}

void publish_state(RemoteControl& r, const params::Params& params, const systems::LiveTuning& tuning) {
    const std::string& prefix = r.settings.prefix;
    if (!r.published || r.published->revision() != params.revision()) {
        for (const params::ParamDecl& d : params::param_decls())
            if (!r.published || r.published->at(d.id) != params.at(d.id))
                r.client->publish(fmt::format("{}/state/{}", prefix, d.name),
                                  remote::set_syntax(params.at(d.id)), true);
        r.client->publish(prefix + "/state", remote::state_document(params), true);
        r.published = std::make_unique<params::Params>(params);
    }
    const std::string& preset = tuning.layers.preset_name();
    if (!r.preset_published || preset != r.published_preset) {
        r.client->publish(prefix + "/preset", preset.empty() ? "none" : preset, true);
        r.published_preset = preset;
        r.preset_published = true;
    }
}

// One line when under-voltage or throttling starts, one when a whole health interval was clear of it.
void log_power_changes(const remote::BoardPower& before, const remote::BoardPower& now) {
    if (now.undervoltage && *now.undervoltage != before.undervoltage.value_or(false)) {
        if (*now.undervoltage)
            spdlog::warn(
                "power: under-voltage on this board (the firmware's flag): the supply or its cable is too "
                "weak; use the board's official supply (5.1 V, 3 A for a Pi 4, 5 A for a Pi 5)");
        else
            spdlog::info("power: the supply has been steady again for a health interval");
    }
    if (now.throttled && *now.throttled != before.throttled.value_or(false)) {
        if (*now.throttled)
            spdlog::warn(
                "power: the board is throttling (frequency capped or at its temperature limit): "
                "frames may come late; check its cooling and supply");
        else
            spdlog::info("power: no throttling for a health interval");
    }
}

void publish_health(RemoteControl& r, const FrameStats::Summary& s) {
    r.board_power.poll();
    const remote::BoardPower power = r.board_power.take();
    log_power_changes(r.last_power, power);
    r.last_power = power;
    remote::Health h{.fps = s.fps,
                     .frame_ms_p95 = s.p95_ms,
                     .cpu_ms_per_frame = s.cpu_ms,
                     .rss_mb = static_cast<double>(read_memory_status().rss_kib) / 1024.0,
                     .uptime_s = monotonic_seconds() - r.started,
                     .camera_dropped_frames = r.camera ? r.camera->faults().dropped : 0,
                     .soc_temperature_c = remote::soc_temperature_c(),
                     .undervoltage = power.undervoltage,
                     .throttled = power.throttled};
    r.client->publish(r.settings.prefix + "/health", remote::health_document(h), true);
}

}  // namespace

void RemoteControl::reply_error(const std::string& topic, const std::string& message) {
    spdlog::warn("{}", message);
    client->publish(settings.prefix + "/error", remote::error_document(topic, message), false);
}

void remote_commands_system(RemoteControl& r, const systems::LiveTuning& tuning, systems::TuningInbox& inbox,
                            systems::FrameCapture& capture) {
    r.client->drain(r.inbox);
    if (const std::uint64_t dropped = r.client->take_dropped())
        r.reply_error(
            "", fmt::format("remote: {} message(s) dropped: more than {:g} a second, or {} waiting", dropped,
                            remote::MqttClient::rate_per_second, remote::MqttClient::inbox_capacity));
    for (const remote::Inbound& m : r.inbox) {
        auto request = remote::parse_request(r.settings, m);
        if (!request) {
            r.reply_error(m.topic, request.error().message);
            continue;
        }
        if (std::holds_alternative<remote::RetainedCommand>(*request)) {
            if (r.retained_reported.insert(m.topic).second)
                r.reply_error(
                    m.topic, fmt::format("remote: {}: retained commands are ignored ('{}' is retained on the "
                                         "broker, which replays it at every connect; clear it with "
                                         "mosquitto_pub -r -n -t '{}')",
                                         safe_quote(m.topic), safe_quote(m.payload), safe_quote(m.topic)));
            continue;
        }
        if (auto applied = apply(r, tuning, inbox, capture, *request); !applied)
            r.reply_error(m.topic, fmt::format("remote: {}: {}", m.topic, applied.error().message));
    }
    r.inbox.clear();
}

void remote_publish_system(RemoteControl& r, const params::Params& params, const systems::LiveTuning& tuning,
                           systems::FrameCapture& capture) {
    r.stats.tick();
    const std::uint64_t connections = r.client->connections();
    const bool reconnected = connections != r.connections_seen;
    r.connections_seen = connections;
    if (r.clear_only) {
        if (reconnected) {
            publish_all(*r.client,
                        remote::clear_discovery(r.settings, tuning.layers.presets().names(), version()));
            spdlog::info("remote: remote.enabled = false: Home Assistant discovery configs cleared");
        }
        return;
    }
    if (r.screenshot_wanted && !capture.image.empty()) {  // the frame just presented, read back before it
        r.screenshot_wanted = false;
        r.encoder->submit([frame = std::move(capture.image), width = r.settings.screenshot_width](
                              std::stop_token) { return screenshot_jpeg(frame, width); });
        capture.image = {};
    }
    if (!r.client->connected()) return;
    if (reconnected) {
        r.published.reset();
        r.preset_published = false;
        r.discovery_due = true;
    }
    if (auto jpeg = r.encoder->take(); jpeg && !jpeg->empty())
        r.client->publish(r.settings.prefix + "/screenshot", std::move(*jpeg), true);
    if (r.discovery_due) {
        r.discovery_due = false;
        publish_all(*r.client,
                    remote::discovery_configs(r.settings, tuning.layers.presets().names(), version(),
                                              {.soc_temperature = remote::soc_temperature_c().has_value(),
                                               .board_power = r.board_power.present()}));
    }
    publish_state(r, params, tuning);
    if (const double now = monotonic_seconds(); r.board_power.present() && now >= r.next_power_poll) {
        r.board_power.poll();  // a dip between two health messages is latched, not missed
        r.next_power_poll = now + 1.0;
    }
    if (const auto s = r.stats.take_report()) publish_health(r, *s);
}

Result<void> add_remote_plugin(ecs::World& world, ecs::Schedule& schedule) {
    const params::Params& params = world.resource<params::Params>();
    const bool enabled = params.get<ParamId::remote_enabled>();
    // A screen leaving the fleet: enabled = false with a broker still named (the shipped config says
    // enabled = false and names none, so an ordinary install never connects).
    const bool clear_only = !enabled && params.source(ParamId::remote_host) != params::ParamSource::Default;
    if (!enabled && !clear_only) return {};
    auto settings = remote::remote_settings(params);
    if (!settings) return settings.error();
    const remote::RemoteSettings& s = *settings;
    remote::ClientOptions options{.host = s.host,
                                  .port = s.port,
                                  .client_id = s.client_id,
                                  .keepalive_s = s.keepalive_s,
                                  .tls_ca = s.tls_ca,
                                  .tls_cert = s.tls_cert,
                                  .tls_key = s.tls_key,
                                  .username = s.username,
                                  .password = s.password,
                                  .availability_topic = s.prefix + "/availability"};
    if (!clear_only) {
        for (const std::string* prefix : {&s.prefix, &s.fleet_prefix})
            if (!prefix->empty())
                for (const char* topic : {"/set/+", "/preset/set", "/command"})
                    options.subscriptions.push_back(*prefix + topic);
        options.subscriptions.push_back(std::string(remote::discovery_root) + "/status");
    }
    auto client = remote::MqttClient::start(std::move(options));
    if (!client) return client.error();
    if (!world.try_resource<systems::TuningInbox>()) world.insert_resource<systems::TuningInbox>();
    auto& r = world.insert_resource<RemoteControl>(std::move(*settings));
    r.client = std::move(*client);
    r.clear_only = clear_only;
    r.inbox.reserve(remote::MqttClient::inbox_capacity);
    r.started = monotonic_seconds();
    r.camera = world.try_resource<systems::CameraFeed>();
    spdlog::info("remote: {} {}:{} as {}, topics under {}{}", clear_only ? "clearing discovery on" : "broker",
                 r.settings.host, r.settings.port, r.settings.client_id, r.settings.prefix,
                 r.settings.fleet_prefix.empty() || clear_only ? "" : " and " + r.settings.fleet_prefix);
    using ecs::Stage;
    if (!clear_only) schedule.add(Stage::Input, "remote commands", remote_commands_system);
    schedule.add(Stage::Present, "remote publish", remote_publish_system);
    return {};
}

}  // namespace puddle::systems
