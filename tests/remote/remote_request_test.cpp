// src/remote without a broker: which parameters are writable, how a message becomes a request or an
// error, the password file rule, and the discovery configs against the registry.

#include "remote/remote_request.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <nlohmann/json.hpp>

#include "remote/discovery.hpp"
#include "remote/state_json.hpp"
#include "support/test_support.hpp"

namespace puddle::remote {
namespace {

using params::ParamId;

RemoteSettings settings(const std::string& writable = "rain.*, look.vignette") {
    RemoteSettings s;
    s.prefix = "puddle/a1";
    s.fleet_prefix = "puddle/all";
    s.client_id = "puddle-a1";
    s.device_id = "a1";
    s.writable = WritablePatterns(writable);
    return s;
}

Result<Request> parse(const std::string& topic, const std::string& payload,
                      const RemoteSettings& s = settings()) {
    return parse_request(s, Inbound{topic, payload, payload.size()});
}

// The request of a message that must parse.
Request ok(const std::string& topic, const std::string& payload) {
    auto r = parse(topic, payload);
    EXPECT_TRUE(r) << topic << ": " << r.error().message;
    return r ? std::move(r).value() : Request(Ignored{});
}

TEST(WritablePatterns, PrefixPatternsAndNamesButNeverDeviceSettings) {
    const WritablePatterns w("rain.*, look.vignette ,, *");
    EXPECT_TRUE(w.allows(params::decl(ParamId::rain_intensity)));
    EXPECT_TRUE(w.allows(params::decl(ParamId::look_vignette)));
    EXPECT_TRUE(w.allows(params::decl(ParamId::water_tint)));  // "*"
    EXPECT_FALSE(w.allows(params::decl(ParamId::display_card)));
    EXPECT_FALSE(w.allows(params::decl(ParamId::remote_host)));
    EXPECT_FALSE(w.allows(params::decl(ParamId::environment_camera_device)));
    EXPECT_FALSE(w.allows(params::decl(ParamId::wall_column)));  // where this screen sits in a wall
    const WritablePatterns narrow("rain.*");
    EXPECT_FALSE(narrow.allows(params::decl(ParamId::look_vignette)));
    EXPECT_FALSE(WritablePatterns("rain").allows(params::decl(ParamId::rain_intensity)));
}

TEST(RemoteRequest, SetUnderEitherPrefixIsParsedLikeSet) {
    for (const char* topic : {"puddle/a1/set/rain.intensity", "puddle/all/set/rain.intensity"}) {
        auto r = parse(topic, " 0.75\n");
        ASSERT_TRUE(r) << r.error().message;
        const auto& set = std::get<SetParam>(*r);
        EXPECT_EQ(set.id, ParamId::rain_intensity);
        EXPECT_EQ(std::get<float>(set.value), 0.75f);
    }
}

TEST(RemoteRequest, ErrorsNameTheTopicAndWhatIsAllowed) {
    auto expect_error = [](Result<Request> r, const std::string& text) {
        ASSERT_FALSE(r) << "accepted; expected: " << text;
        EXPECT_NE(r.error().message.find(text), std::string::npos) << r.error().message;
    };
    expect_error(parse("puddle/a1/set/rain.intensity", "5"),
                 "remote: puddle/a1/set/rain.intensity: rain.intensity = 5 is out of range");
    expect_error(parse("puddle/a1/set/rain.drop_count", "2.5"), "rain.drop_count");
    expect_error(parse("puddle/a1/set/rain.intensty", "1"),
                 "unknown parameter 'rain.intensty' (did you mean 'rain.intensity'?)");
    expect_error(parse("puddle/a1/set/water.tint", "0,0,0"),
                 "water.tint cannot be set remotely (not in remote.writable)");
    expect_error(parse("puddle/a1/set/display.mode", "640x480"), "a setting of the device itself");
    expect_error(parse("puddle/a1/command", "format-disk"), "unknown command 'format-disk'");
    expect_error(parse("puddle/a1/other", "x"), "not a command topic");
    expect_error(
        parse_request(settings(), Inbound{"puddle/a1/set/rain.intensity", "", max_payload_bytes + 1}),
        "payload of 4097 bytes refused (at most 4096)");
}

TEST(RemoteRequest, CommandsPresetsAndHomeAssistant) {
    EXPECT_EQ(std::get<Command>(ok("puddle/a1/command", "next-preset")), Command::NextPreset);
    EXPECT_EQ(std::get<Command>(ok("puddle/all/command", "screenshot")), Command::Screenshot);
    EXPECT_EQ(std::get<SelectPreset>(ok("puddle/a1/preset/set", "downpour")).name, "downpour");
    EXPECT_EQ(std::get<SelectPreset>(ok("puddle/a1/preset/set", "none")).name, "");
    EXPECT_TRUE(std::holds_alternative<HomeAssistantOnline>(ok("homeassistant/status", "online")));
    EXPECT_TRUE(std::holds_alternative<Ignored>(ok("homeassistant/status", "offline")));
}

// A command is an event: a retained one (replayed by the broker at every subscription) is never
// applied, whatever it holds, on every command topic and under either prefix; an empty payload is a
// retained message being cleared, not an error. homeassistant/status is a state and may be retained.
TEST(RemoteRequest, RetainedCommandsAreNeverAppliedAndAnEmptyPayloadIsCleared) {
    for (const char* topic :
         {"puddle/a1/command", "puddle/all/command", "puddle/a1/preset/set", "puddle/all/preset/set",
          "puddle/a1/set/rain.intensity", "puddle/all/set/rain.intensty"}) {
        for (const char* payload : {"next-preset", "0.5", "downpour", "", "junk"}) {
            auto r = parse_request(settings(), Inbound{topic, payload, std::string(payload).size(), true});
            ASSERT_TRUE(r) << topic << " " << payload << ": " << r.error().message;
            EXPECT_TRUE(std::holds_alternative<RetainedCommand>(*r)) << topic << " " << payload;
        }
        auto oversized = parse_request(settings(), Inbound{topic, "", max_payload_bytes + 1, true});
        ASSERT_TRUE(oversized) << oversized.error().message;
        EXPECT_TRUE(std::holds_alternative<RetainedCommand>(*oversized));
        for (const char* empty : {"", " \n"})
            EXPECT_TRUE(std::holds_alternative<Ignored>(ok(topic, empty))) << topic;
    }
    auto status = parse_request(settings(), Inbound{"homeassistant/status", "online", 6, true});
    ASSERT_TRUE(status);
    EXPECT_TRUE(std::holds_alternative<HomeAssistantOnline>(*status));
    // Not retained, the same messages apply as before.
    EXPECT_EQ(std::get<Command>(ok("puddle/a1/command", "next-preset")), Command::NextPreset);
}

// A wall's screens switch together at a time the message names.
TEST(RemoteRequest, ApplyAtIsTakenOffTheValueAsNanosecondsSinceTheEpoch) {
    const auto set = std::get<SetParam>(ok("puddle/all/set/rain.intensity", "0.75 apply_at=1764590402.5"));
    EXPECT_EQ(std::get<float>(set.value), 0.75f);
    ASSERT_TRUE(set.apply_at_ns);
    EXPECT_EQ(*set.apply_at_ns, 1'764'590'402'500'000'000LL);
    EXPECT_FALSE(std::get<SetParam>(ok("puddle/all/set/rain.intensity", "0.75")).apply_at_ns);
    const auto preset = std::get<SelectPreset>(ok("puddle/all/preset/set", "downpour apply_at=1764590403"));
    EXPECT_EQ(preset.name, "downpour");
    EXPECT_EQ(preset.apply_at_ns, 1'764'590'403'000'000'000LL);
    for (const char* bad :
         {"0.75 apply_at=", "0.75 apply_at=soon", "0.75 apply_at=-3", "0.75 apply_at=1e30"}) {
        auto r = parse("puddle/all/set/rain.intensity", bad);
        ASSERT_FALSE(r) << bad;
        EXPECT_NE(r.error().message.find("remote: puddle/all/set/rain.intensity: apply_at '"),
                  std::string::npos)
            << r.error().message;
        EXPECT_NE(r.error().message.find("is not a time in seconds since the Unix epoch"), std::string::npos);
    }
}

TEST(RemoteSettings, AWorldReadablePasswordFileIsRefused) {
    test::TempDir dir;
    const std::string file = dir.write("pw", "s3cret\nignored\n");
    chmod(file.c_str(), 0600);
    auto ok = read_password_file(file);
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(*ok, "s3cret");
    chmod(file.c_str(), 0644);
    auto refused = read_password_file(file);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().message,
              fmt::format("remote: remote.password_file = {}: others may read it; refused (chmod 600 {})",
                          file, file));
    EXPECT_EQ(refused.error().code, ExitCode::Config);
}

TEST(RemoteState, SetSyntaxReadsBackAsTheSameValue) {
    const params::Params p;
    for (const params::ParamDecl& d : params::param_decls()) {
        if (d.kind == params::ParamKind::Path) continue;  // empty text: nothing to parse
        auto back = params::parse_value(d, set_syntax(p.at(d.id)));
        ASSERT_TRUE(back) << d.name << ": " << back.error().message;
        EXPECT_EQ(*back, p.at(d.id)) << d.name;
    }
    const auto doc = nlohmann::json::parse(state_document(p));
    EXPECT_EQ(doc.size(), params::param_count);
    EXPECT_EQ(doc["rain.intensity"], 0.3);
    EXPECT_EQ(doc["water.tint"], nlohmann::json::parse("[0.02, 0.04, 0.05]"));
}

// A payload of any bytes may be quoted in an error: one 0xff byte made nlohmann's dump() throw, and the
// exception ended the process (and, retained on a fleet topic, every screen at each start).
TEST(RemoteState, AnErrorQuotingBytesThatAreNotUtf8IsStillValidJson) {
    const std::string message = "remote: set/rain.intensity: '\xff\xfe' is not a number";
    std::string document;
    ASSERT_NO_THROW(document = error_document("puddle/t/set/rain.intensity", message));
    const auto doc = nlohmann::json::parse(document);
    EXPECT_EQ(doc["topic"], "puddle/t/set/rain.intensity");
    EXPECT_EQ(doc["error"], "remote: set/rain.intensity: '\xef\xbf\xbd\xef\xbf\xbd' is not a number")
        << "each bad byte becomes U+FFFD";
}

TEST(Discovery, OneControlPerWritableParameterWithTheRegistrysRange) {
    const RemoteSettings s = settings("rain.*, look.*, overlay.rain");
    const auto configs =
        discovery_configs(s, {"downpour", "drizzle"}, "9.9", {.soc_temperature = true, .board_power = true});
    std::size_t params_seen = 0;
    for (const Outbound& o : configs) {
        SCOPED_TRACE(o.topic);
        EXPECT_TRUE(o.retain);
        const auto c = nlohmann::json::parse(o.payload);
        EXPECT_TRUE(o.topic.starts_with("homeassistant/") && o.topic.ends_with("/config"));
        EXPECT_EQ(c["device"]["identifiers"][0], "puddle-a1");
        EXPECT_EQ(c["device"]["sw_version"], "9.9");
        if (!c.contains("command_topic") ||
            !c["command_topic"].get<std::string>().starts_with("puddle/a1/set/"))
            continue;
        ++params_seen;
        const auto* d = params::find_param(c["command_topic"].get<std::string>().substr(14));
        ASSERT_NE(d, nullptr);
        EXPECT_TRUE(s.writable.allows(*d));
        if (d->kind == params::ParamKind::Int || d->kind == params::ParamKind::Float) {
            EXPECT_EQ(c["min"].get<double>(), d->min);
            EXPECT_EQ(c["max"].get<double>(), d->max);
            EXPECT_TRUE(o.topic.starts_with("homeassistant/number/"));
        }
    }
    std::size_t writable = 0;
    for (const params::ParamDecl& d : params::param_decls()) writable += s.writable.allows(d);
    EXPECT_EQ(params_seen, writable);
    const auto cleared = clear_discovery(s, {"downpour", "drizzle"}, "9.9");
    ASSERT_EQ(cleared.size(), configs.size());
    for (std::size_t i = 0; i < cleared.size(); ++i) {
        EXPECT_EQ(cleared[i].topic, configs[i].topic);
        EXPECT_TRUE(cleared[i].payload.empty() && cleared[i].retain);
    }
}

// Issue 33, item 10: Home Assistant 2025.10 and later read default_entity_id ("<domain>.<slug>"), not
// object_id, and made entity ids from the device's name and the raw key
// (number.puddle_puddle_hatest_rain_drop_count); the names were raw keys (rain.drop_count, next-preset).
TEST(Discovery, EveryEntityHasAReadableNameAndBothEntityIdKeys) {
    RemoteSettings s = settings("rain.*, look.*, overlay.rain, scene.kind");
    s.client_id = "puddle-Lobby.2";
    s.screen_name = "Lobby.2";
    EXPECT_EQ(device_name(s), "Puddle Lobby.2");
    s.screen_name.clear();
    EXPECT_EQ(device_name(s), "Puddle puddle-Lobby.2") << "no screen name: the client id";
    s.screen_name = "lobby";
    std::map<std::string, std::string> names;  // default_entity_id -> name
    for (const Outbound& o :
         discovery_configs(s, {"downpour"}, "9.9", {.soc_temperature = true, .board_power = true})) {
        SCOPED_TRACE(o.topic);
        const auto c = nlohmann::json::parse(o.payload);
        const std::string component = o.topic.substr(14, o.topic.find('/', 14) - 14);
        const std::string id = c["default_entity_id"], object = c["object_id"], name = c["name"];
        EXPECT_EQ(id, component + "." + object);
        EXPECT_TRUE(object.starts_with("puddle_lobby_2_")) << object;
        EXPECT_EQ(object.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_"), std::string::npos);
        EXPECT_EQ(object.find("__"), std::string::npos);
        EXPECT_FALSE(name.empty());
        EXPECT_TRUE(std::isupper(static_cast<unsigned char>(name[0]))) << name;
        EXPECT_EQ(name.find_first_of("._"), std::string::npos) << "a raw key: " << name;
        EXPECT_FALSE(name.starts_with("Puddle")) << "Home Assistant puts the device's name first";
        EXPECT_EQ(c["device"]["name"], "Puddle lobby");
        EXPECT_TRUE(names.emplace(id, name).second) << "two entities with one id";
    }
    EXPECT_EQ(names["number.puddle_lobby_2_rain_drop_count"], "Rain drop count");
    EXPECT_EQ(names["button.puddle_lobby_2_next_preset"], "Next preset");
    EXPECT_EQ(names["select.puddle_lobby_2_preset"], "Preset");
    EXPECT_EQ(names["select.puddle_lobby_2_scene_kind"], "Scene kind");
    EXPECT_EQ(names["sensor.puddle_lobby_2_soc_temperature_c"], "SoC temperature");
    EXPECT_EQ(names["image.puddle_lobby_2_screenshot"], "Screenshot");
    EXPECT_EQ(names["binary_sensor.puddle_lobby_2_undervoltage"], "Under-voltage");
    EXPECT_EQ(names["binary_sensor.puddle_lobby_2_throttled"], "Throttled");
    EXPECT_EQ(readable_name("overlay.rain"), "Overlay rain");
}

// The SoC temperature sensor is announced only where the screen has a thermal zone; clearing removes it
// either way (it may have been announced before, on other hardware or another kernel).
TEST(Discovery, TheTemperatureSensorOnlyWhereThereIsAThermalZone) {
    const RemoteSettings s = settings("rain.*");
    const auto has_temperature = [](const std::vector<Outbound>& out) {
        return std::any_of(out.begin(), out.end(), [](const Outbound& o) {
            return o.topic.find("/soc_temperature_c/") != std::string::npos;
        });
    };
    const auto with = discovery_configs(s, {}, "9.9", {.soc_temperature = true});
    const auto without = discovery_configs(s, {}, "9.9", {.soc_temperature = false});
    EXPECT_TRUE(has_temperature(with));
    EXPECT_FALSE(has_temperature(without));
    EXPECT_EQ(with.size(), without.size() + 1);
    EXPECT_TRUE(has_temperature(clear_discovery(s, {}, "9.9")));
}

// A Raspberry Pi's under-voltage and throttling are binary sensors ("problem": on is trouble) read from the
// health message, announced only on a board that reports them; clearing removes them either way.
TEST(Discovery, ThePowerSensorsOnlyOnABoardThatReportsThem) {
    const RemoteSettings s = settings("rain.*");
    const auto power_sensors = [](const std::vector<Outbound>& out) {
        std::vector<nlohmann::json> found;
        for (const Outbound& o : out)
            if (o.topic.starts_with("homeassistant/binary_sensor/") && !o.payload.empty())
                found.push_back(nlohmann::json::parse(o.payload));
        return found;
    };
    const auto with = discovery_configs(s, {}, "9.9", {.board_power = true});
    const auto without = discovery_configs(s, {}, "9.9", {});
    EXPECT_EQ(with.size(), without.size() + 2);
    EXPECT_TRUE(power_sensors(without).empty());
    const auto sensors = power_sensors(with);
    ASSERT_EQ(sensors.size(), 2u);
    for (const auto& c : sensors) {
        EXPECT_EQ(c["device_class"], "problem");
        EXPECT_EQ(c["state_topic"], "puddle/a1/health");
        EXPECT_EQ(c["entity_category"], "diagnostic");
    }
    EXPECT_EQ(sensors[0]["value_template"], "{{ 'ON' if value_json.undervoltage else 'OFF' }}");
    EXPECT_EQ(sensors[1]["value_template"], "{{ 'ON' if value_json.throttled else 'OFF' }}");
    const auto cleared = clear_discovery(s, {}, "9.9");
    EXPECT_EQ(
        std::count_if(cleared.begin(), cleared.end(),
                      [](const Outbound& o) { return o.topic.starts_with("homeassistant/binary_sensor/"); }),
        2);
}

}  // namespace
}  // namespace puddle::remote
