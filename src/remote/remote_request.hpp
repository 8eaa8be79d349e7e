#pragma once
// A message from the broker, checked the way the config is (registry.hpp's parse_value: the same value
// syntax as --set, the kind and range of the declaration) plus the writable patterns, turned into what
// it asks for. A bad message is an error naming its topic, and nothing of it applies.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "params/registry.hpp"
#include "remote/remote_settings.hpp"
#include "util/result.hpp"

namespace puddle::remote {

// Payloads longer than this are refused unread (a parameter's value, a preset's name and a command are
// short).
inline constexpr std::size_t max_payload_bytes = 4096;

// As the network thread hands it over. `size` is the payload's size on the wire; an oversized payload
// arrives with `payload` empty. `retained`: the broker's retain flag, set when the message comes from
// its store (replayed at every subscription, so at every reconnect and restart), not sent just now.
struct Inbound {
    std::string topic;
    std::string payload;
    std::size_t size = 0;
    bool retained = false;
};

// When a change is to apply, for the screens of a wall (wall.clock = "realtime"): nanoseconds since the
// Unix epoch; none: at the next change boundary (systems/tuning/synced_changes.hpp). A payload asks for it by
// ending in " apply_at=<seconds since the Unix epoch>", e.g. "0.5 apply_at=1764590402.5".
using ApplyAt = std::optional<std::int64_t>;

struct SetParam {
    params::ParamId id;
    params::ParamValue value;
    ApplyAt apply_at_ns;
};
struct SelectPreset {
    std::string name;  // "" (spelled "none" on the topic): the config's preset
    ApplyAt apply_at_ns;
};
enum class Command { NextPreset, PreviousPreset, Save, Screenshot, Reload };
struct HomeAssistantOnline {};  // homeassistant/status = online: publish discovery again
// homeassistant/status = offline; an empty payload on a command topic (a retained message cleared:
// `mosquitto_pub -r -n`, which the broker passes on to those subscribed).
struct Ignored {};
// A retained message on a command topic: not applied. A command is an event; a retained one would be
// replayed at every reconnect and restart (a preset stepped and saved each time, a set overriding every
// later one).
struct RetainedCommand {};
using Request = std::variant<SetParam, SelectPreset, Command, HomeAssistantOnline, Ignored, RetainedCommand>;

// Topics: <prefix>/set/<parameter>, <prefix>/preset/set and <prefix>/command, under `settings.prefix`
// or `settings.fleet_prefix` (the command topics: never retained, RetainedCommand; an empty payload is
// Ignored), and homeassistant/status (a state: may be retained); set and preset/set payloads may end in an
// apply_at (above). Errors (one line, "remote: TOPIC: why"): payload
// too large, a topic that is none of these, an unknown parameter (with the nearest name), one that is not
// writable (remote.writable), a value of the wrong kind or out of range (what is allowed), an unknown
// command (the list), an apply_at that is not a time.
Result<Request> parse_request(const RemoteSettings& settings, const Inbound& message);

// The commands as spelled on <prefix>/command, in Command's order.
inline constexpr const char* command_names[] = {"next-preset", "previous-preset", "save", "screenshot",
                                                "reload"};

}  // namespace puddle::remote
