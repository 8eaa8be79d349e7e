#pragma once
// Home Assistant MQTT discovery (https://www.home-assistant.io/integrations/mqtt/#mqtt-discovery): one
// retained config per entity under homeassistant/<component>/<node id>/<object id>/config, all naming
// the same device (identifiers, name, model, software version), generated from the registry. Each has
// a readable name ("Rain drop count", "Next preset") shown after the device's ("Puddle lobby"), and its
// entity id as both object_id (Home Assistant before 2025.10) and default_entity_id ("number.
// puddle_lobby_rain_drop_count"; 2025.10 and later, which ignore object_id from 2026.4):
//   number  an int or float parameter (min, max, step and unit from its declaration)
//   select  an enum parameter, and the preset
//   switch  a bool parameter
//   text    a text or three-number parameter (three numbers are written "x,y,z")
//   button  each command of <prefix>/command
//   sensor  each health field (health.hpp), diagnostic
//   image   the screenshot topic (JPEG)
// Only writable parameters (remote.writable) become controls. An empty retained payload on the same
// topics removes the entities (clear_discovery).

#include <string>
#include <string_view>
#include <vector>

#include "remote/mqtt_client.hpp"
#include "remote/remote_settings.hpp"

namespace puddle::remote {

inline constexpr const char* discovery_root = "homeassistant";

// The client id (default puddle-<device id>), with every character other than letters, digits, '_' and
// '-' as '_': unique per screen, as the broker already requires of client ids.
std::string node_id(const RemoteSettings& settings);
// A key as people read it: "rain.drop_count" -> "Rain drop count", "next-preset" -> "Next preset".
std::string readable_name(std::string_view key);
// "Puddle <settings.screen_name>" ("Puddle lobby"), the client id where there is no screen name.
std::string device_name(const RemoteSettings& settings);

// Which health sensors this screen has: the SoC temperature only where /sys/class/thermal has a zone, the
// power flags only on a Raspberry Pi that reports them, so that Home Assistant shows no sensor that stays
// "unknown".
struct HealthSensors {
    bool soc_temperature = false;
    bool board_power = false;  // under-voltage and throttling (remote/board_power.hpp), as binary sensors
};

// Every discovery config, retained. `presets`: the preset names the select offers ("none" is added).
std::vector<Outbound> discovery_configs(const RemoteSettings& settings,
                                        const std::vector<std::string>& presets, std::string_view version,
                                        HealthSensors sensors);
// Every topic discovery_configs can announce (all sensors) with empty retained payloads: Home Assistant
// removes the entities.
std::vector<Outbound> clear_discovery(const RemoteSettings& settings, const std::vector<std::string>& presets,
                                      std::string_view version);

}  // namespace puddle::remote
