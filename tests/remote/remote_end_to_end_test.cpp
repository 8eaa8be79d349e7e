// The puddle binary against a real Mosquitto broker: commands change the picture,
// bad messages are refused with a reply, Home Assistant discovery matches the registry, screenshots are
// JPEGs of the asked width, the client survives a broker restart and an outage, and the broker delivers
// the last will when the process is killed. Skipped when mosquitto is not installed.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <set>
#include <span>
#include <thread>

#include "camera/mjpeg_decoder.hpp"
#include "params/registry.hpp"
#include "remote/remote_request.hpp"
#include "remote/writable_patterns.hpp"
#include "support/blackhole_port.hpp"
#include "support/mosquitto_broker.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"
#include "util/monotonic_clock.hpp"
#include "util/valid_utf8.hpp"

namespace puddle::test {
namespace {

using nlohmann::json;

constexpr const char* prefix = "puddle/e2e";

std::string remote_config(int port, const std::string& extra = "") {
    return fmt::format(
        "[remote]\nenabled = true\nport = {}\nprefix = \"{}\"\nclient_id = \"puddle-e2e\"\n"
        "health_interval = 1\nscreenshot_width = 160\n{}",
        port, prefix, extra);
}

std::vector<std::string> puddle_args(const TempDir& dir) {
    return {"--config",  (dir / "puddle.toml").string(),
            "--state",   (dir / "state.toml").string(),
            "-b",        "headless",
            "--size",    "320x180",
            "--frames",  "0",
            "--fps-cap", "30"};
}

// The mean luma of the four corners (a tenth of the width and height each) of a JPEG decoded at its
// expected size; the test fails when it does not decode.
double jpeg_corner_luma(const std::string& jpeg, int width, int height) {
    camera::MjpegDecoder decoder;
    auto r = decoder.decode(std::as_bytes(std::span(jpeg.data(), jpeg.size())), width, height);
    EXPECT_TRUE(r) << (r ? "" : r.error().message);
    if (!r) return -1;
    const auto px = decoder.rgba();
    const int cw = width / 10, ch = height / 10;
    double sum = 0;
    int n = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if ((x >= cw && x < width - cw) || (y >= ch && y < height - ch)) continue;
            const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
            sum += 0.2126 * std::to_integer<int>(px[i]) + 0.7152 * std::to_integer<int>(px[i + 1]) +
                   0.0722 * std::to_integer<int>(px[i + 2]);
            ++n;
        }
    return sum / n;
}

class RemoteEndToEnd : public ::testing::Test {
protected:
    void SetUp() override {
        if (!mosquitto_available()) GTEST_SKIP() << no_mosquitto;
        broker = std::make_unique<MosquittoBroker>();
        ASSERT_TRUE(broker->running()) << broker->log();
        client = std::make_unique<MqttTestClient>(MqttTestClient::Options{.port = broker->port()});
        ASSERT_TRUE(client->connected());
        client->subscribe(std::string(prefix) + "/#");
    }
    // Starts puddle with the [remote] section and waits until it says `online`.
    void start_puddle(const std::string& extra = "") {
        dir.write("puddle.toml", remote_config(broker->port(), extra));
        puddle = std::make_unique<Running>(puddle_args(dir), dir / "puddle.log");
        ASSERT_TRUE(client->wait_for(
            topic("availability"), [](auto& p) { return p == "online"; }, 60))
            << puddle->log();
    }
    static std::string topic(const std::string& rest) { return std::string(prefix) + "/" + rest; }
    std::optional<std::string> wait_state(const std::string& name, const std::string& value) {
        return client->wait_for(topic("state/" + name), [&](const std::string& p) { return p == value; });
    }

    TempDir dir;
    std::unique_ptr<MosquittoBroker> broker;
    std::unique_ptr<MqttTestClient> client;
    std::unique_ptr<Running> puddle;
};

TEST_F(RemoteEndToEnd, SetChangesThePictureAndIsSavedAsRemote) {
    start_puddle();
    // A screenshot with no vignette, then one with the strongest: the corners darken.
    auto shot = [&](const std::string& vignette) {
        client->publish(topic("set/look.vignette"), vignette);
        EXPECT_TRUE(wait_state("look.vignette", vignette)) << puddle->log();
        const std::size_t before = client->received(topic("screenshot")).size();
        client->publish(topic("command"), "screenshot");
        const auto jpeg = client->wait_for_more(topic("screenshot"), before);
        EXPECT_TRUE(jpeg) << puddle->log();
        return jpeg.value_or("");
    };
    const std::string plain = shot("0"), dark = shot("1.4");
    const double plain_corner = jpeg_corner_luma(plain, 160, 90),
                 dark_corner = jpeg_corner_luma(dark, 160, 90);
    EXPECT_LT(dark_corner, plain_corner * 0.6)
        << "look.vignette 1.4 did not darken the corners: " << plain_corner << " -> " << dark_corner;
    const auto doc = json::parse(client->latest()[topic("state")]);
    EXPECT_EQ(doc["look.vignette"], 1.4);

    EXPECT_EQ(puddle->stop(), 0);
    const std::string state = read_file(dir / "state.toml");
    EXPECT_NE(state.find("remote = [\"look.vignette\"]"), std::string::npos) << state;
    const auto printed =
        run_puddle(fmt::format("--config {} --state {} --print-config", (dir / "puddle.toml").string(),
                               (dir / "state.toml").string()));
    EXPECT_NE(printed.output.find("look.vignette              = 1.4                      # remote"),
              std::string::npos)
        << printed.output;
}

TEST_F(RemoteEndToEnd, BadMessagesAreRefusedWithAnErrorReplyAndNothingApplies) {
    start_puddle();
    ASSERT_TRUE(wait_state("rain.intensity", "0.3"));
    struct Case {
        std::string topic, payload, says;
    };
    const std::vector<Case> cases{
        {topic("set/rain.intensity"), "9", "out of range"},
        {topic("set/rain.intensty"), "0.5",
         "unknown parameter 'rain.intensty' (did you mean 'rain.intensity'?)"},
        {topic("set/display.card"), "/dev/dri/card0", "display.card cannot be set remotely"},
        {topic("set/remote.host"), "evil.example", "remote.host cannot be set remotely"},
        {topic("set/environment.image"), "/etc/shadow", "not in remote.writable"},
        {topic("set/rain.intensity"), std::string(remote::max_payload_bytes + 1, '1'),
         "payload of 4097 bytes"},
        {topic("set/rain.intensity"), "lots", "rain.intensity"},
        {topic("command"), "self-destruct", "unknown command"},
        {topic("preset/set"), "no-such-preset", "no-such-preset"},
        {topic("command"), "\xff\xfenext\xc0", "unknown command"},  // not UTF-8
    };
    for (const Case& c : cases) {
        client->publish(c.topic, c.payload);
        const auto reply = client->wait_for(topic("error"), [&](const std::string& p) {
            const auto j = json::parse(p);
            return j["topic"] == c.topic && j["error"].get<std::string>().find(c.says) != std::string::npos;
        });
        EXPECT_TRUE(reply) << c.topic << " " << c.payload.substr(0, 20) << ": no error reply saying '"
                           << c.says << "'\n"
                           << puddle->log();
    }
    // A good message after them all still applies, and none of the bad ones did.
    client->publish(topic("set/rain.intensity"), "0.5");
    ASSERT_TRUE(wait_state("rain.intensity", "0.5"));
    const auto state = json::parse(client->latest()[topic("state")]);
    EXPECT_EQ(state["display.card"], "");
    EXPECT_EQ(state["remote.host"], "localhost");
    EXPECT_EQ(state["environment.image"], "");
    EXPECT_EQ(client->received(topic("state/rain.intensity")), (std::vector<std::string>{"0.3", "0.5"}));
    // Issue 33, item 10: the log quotes the bad payload as valid UTF-8 (U+FFFD for each bad byte).
    const std::string log = puddle->log();
    EXPECT_TRUE(is_valid_utf8(log)) << log;
    EXPECT_NE(log.find("unknown command '\xef\xbf\xbd\xef\xbf\xbdnext\xef\xbf\xbd'"), std::string::npos)
        << log;
}

TEST_F(RemoteEndToEnd, DiscoveryConfigsAreValidAndTheirRangesAreTheRegistrys) {
    client->subscribe("homeassistant/#");
    start_puddle();
    ASSERT_TRUE(client->wait_for("homeassistant/image/puddle-e2e/screenshot/config"));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    int numbers = 0, controls = 0;
    std::set<std::string> components;
    for (const auto& [t, payload] : client->latest()) {
        if (!t.starts_with("homeassistant/")) continue;
        SCOPED_TRACE(t);
        ASSERT_TRUE(json::accept(payload)) << payload;
        const json c = json::parse(payload);
        const std::string component = t.substr(14, t.find('/', 14) - 14);
        components.insert(component);
        EXPECT_TRUE(c.contains("name") && c.contains("unique_id") && c.contains("availability_topic"));
        EXPECT_EQ(c["device"]["identifiers"][0], "puddle-e2e");
        EXPECT_EQ(c["device"]["name"], "Puddle e2e");
        EXPECT_EQ(c["default_entity_id"], component + "." + c["object_id"].get<std::string>());
        EXPECT_EQ(c["name"].get<std::string>().find_first_of("._"), std::string::npos) << c["name"];
        EXPECT_TRUE(c["device"].contains("sw_version") && c["device"].contains("model"));
        if (component == "sensor") {
            EXPECT_EQ(c["state_topic"], topic("health"));
            continue;
        }
        if (component == "image") {
            EXPECT_EQ(c["image_topic"], topic("screenshot"));
            continue;
        }
        ASSERT_TRUE(c.contains("command_topic"));
        ++controls;
        const std::string command = c["command_topic"];
        if (!command.starts_with(topic("set/"))) continue;
        const std::string name = command.substr(topic("set/").size());
        const params::ParamDecl* d = params::find_param(name);
        ASSERT_NE(d, nullptr) << name;
        EXPECT_FALSE(name.starts_with("display.") || name.starts_with("remote.")) << name;
        if (component == "number") {
            ++numbers;
            EXPECT_EQ(c["min"].get<double>(), d->min);
            EXPECT_EQ(c["max"].get<double>(), d->max);
        }
        if (component == "select") {
            const std::vector<std::string_view> choices(d->choices.begin(), d->choices.end());
            EXPECT_EQ(c["options"].get<std::vector<std::string>>(),
                      std::vector<std::string>(choices.begin(), choices.end()));
        }
    }
    EXPECT_EQ(components,
              (std::set<std::string>{"button", "image", "number", "select", "sensor", "switch", "text"}));
    // One control per writable parameter (remote.writable's default), plus the preset and the commands.
    const remote::WritablePatterns writable(
        std::get<std::string>(params::decl(params::ParamId::remote_writable).default_value));
    int writable_numbers = 0, writable_all = 0;
    for (const params::ParamDecl& d : params::param_decls()) {
        if (!writable.allows(d)) continue;
        ++writable_all;
        writable_numbers += d.kind == params::ParamKind::Int || d.kind == params::ParamKind::Float;
    }
    EXPECT_EQ(numbers, writable_numbers);
    EXPECT_EQ(controls, writable_all + 1 + 5);

    // Home Assistant restarting: discovery again.
    const std::size_t before = client->received("homeassistant/image/puddle-e2e/screenshot/config").size();
    client->publish("homeassistant/status", "online");
    EXPECT_TRUE(client->wait_for_more("homeassistant/image/puddle-e2e/screenshot/config", before));

    // remote.enabled = false with the broker named, then a run: the configs are cleared (empty retained
    // payloads).
    EXPECT_EQ(puddle->stop(), 0);
    dir.write("puddle.toml", fmt::format("[remote]\nenabled = false\nhost = \"localhost\"\nport = {}\nprefix "
                                         "= \"{}\"\nclient_id = \"puddle-e2e\"\n",
                                         broker->port(), prefix));
    Running clearing(puddle_args(dir), dir / "clear.log");
    ASSERT_TRUE(clearing.wait_for("discovery configs cleared")) << clearing.log();
    EXPECT_EQ(clearing.stop(), 0);
    MqttTestClient fresh({.port = broker->port()});
    fresh.subscribe("homeassistant/#");
    std::this_thread::sleep_for(std::chrono::seconds(1));
    EXPECT_TRUE(fresh.latest().empty()) << fresh.latest().begin()->first << " is still retained";
}

TEST_F(RemoteEndToEnd, HealthIsPublishedEverySecond) {
    start_puddle();
    const auto health =
        client->wait_for(topic("health"), [](auto& p) { return json::parse(p)["uptime_s"] >= 2; });
    ASSERT_TRUE(health) << puddle->log();
    const json h = json::parse(*health);
    EXPECT_GT(h["fps"].get<double>(), 0);
    EXPECT_GT(h["frame_ms_p95"].get<double>(), 0);
    EXPECT_GT(h["rss_mb"].get<double>(), 10);
    EXPECT_EQ(h["camera_dropped_frames"], 0);
}

// A flood past the rate limit (a slider dragged in Home Assistant): the newest value is the one that
// stays, on screen and in the state. Before, the limit dropped the latest messages and left an old one.
TEST_F(RemoteEndToEnd, AFloodPastTheRateLimitEndsOnTheNewestValue) {
    start_puddle();
    ASSERT_TRUE(wait_state("rain.intensity", "0.3"));
    for (int i = 1; i <= 150; ++i)
        client->publish(topic("set/rain.intensity"), fmt::format("{}", i % 9 * 0.1 + 1));
    // The last sent: 150 % 9 = 6, so 1.6.
    EXPECT_TRUE(wait_state("rain.intensity", "1.6")) << puddle->log();
}

TEST_F(RemoteEndToEnd, FleetPrefixReachesTheScreen) {
    start_puddle();
    ASSERT_TRUE(wait_state("look.vignette", "0.5"));
    client->publish("puddle/all/set/look.vignette", "1.2");
    EXPECT_TRUE(wait_state("look.vignette", "1.2")) << puddle->log();
}

TEST_F(RemoteEndToEnd, BrokerRestartReconnectsAndRepublishesAndTheDisplayRunsOn) {
    start_puddle();
    ASSERT_TRUE(wait_state("rain.intensity", "0.3"));
    client.reset();
    broker->stop();
    // Several seconds without a broker: the frames go on (health resumes with a larger uptime below).
    std::this_thread::sleep_for(std::chrono::seconds(3));
    ASSERT_TRUE(puddle->running());
    ASSERT_TRUE(broker->start());
    client = std::make_unique<MqttTestClient>(MqttTestClient::Options{.port = broker->port()});
    client->subscribe(std::string(prefix) + "/#");
    // A restarted broker has no retained messages: these come from the reconnected screen.
    EXPECT_TRUE(client->wait_for(
        topic("availability"), [](auto& p) { return p == "online"; }, 60))
        << puddle->log();
    EXPECT_TRUE(wait_state("rain.intensity", "0.3"));
    const auto health =
        client->wait_for(topic("health"), [](auto& p) { return json::parse(p)["uptime_s"] >= 4; });
    ASSERT_TRUE(health);
    EXPECT_GT(json::parse(*health)["fps"].get<double>(), 1) << "the display stalled during the outage";
    EXPECT_EQ(puddle->count("remote: localhost:" + std::to_string(broker->port()) + ": lost the broker"), 1)
        << puddle->log();
}

// Issue 33, item 4: a retained next-preset stepped (and saved) the preset at every reconnect, and a
// retained set overrode every later plain one. A broker with persistence keeps them across its restart,
// as a real one does: ignored each time, said once per topic, and clearing them is no error.
TEST_F(RemoteEndToEnd, RetainedCommandsAreIgnoredAtEveryReconnectAndSaidOncePerTopic) {
    const int port = free_port();
    const auto store = dir / "broker";
    std::filesystem::create_directories(store);
    client.reset();
    broker = std::make_unique<MosquittoBroker>(
        port, fmt::format("listener {} 127.0.0.1\nallow_anonymous true\nuser root\npersistence true\n"
                          "persistence_location {}/\n",
                          port, store.string()));
    ASSERT_TRUE(broker->running()) << broker->log();
    auto connect_client = [&] {
        client = std::make_unique<MqttTestClient>(MqttTestClient::Options{.port = port});
        ASSERT_TRUE(client->connected());
        client->subscribe(std::string(prefix) + "/#");
    };
    connect_client();
    client->publish(topic("command"), "next-preset", true);
    client->publish(topic("set/rain.intensity"), "0.9", true);
    ASSERT_TRUE(client->wait_for(topic("set/rain.intensity")));  // stored on the broker

    start_puddle();
    // A plain set after the retained messages: when its state comes back, they have been handled.
    auto handled_after = [&](const std::string& vignette) {
        client->publish(topic("set/look.vignette"), vignette);
        ASSERT_TRUE(wait_state("look.vignette", vignette)) << puddle->log();
    };
    handled_after("0.5");
    for (int restart = 0; restart < 2; ++restart) {
        client.reset();
        broker->stop();
        ASSERT_TRUE(broker->start()) << broker->log();
        connect_client();
        ASSERT_TRUE(client->wait_for(
            topic("availability"), [](auto& p) { return p == "online"; }, 60))
            << puddle->log();
        handled_after(restart == 0 ? "0.6" : "0.7");
    }
    EXPECT_EQ(client->latest()[topic("preset")], "none") << puddle->log();
    EXPECT_EQ(client->latest()[topic("state/rain.intensity")], "0.3") << puddle->log();
    EXPECT_EQ(puddle->count("remote: " + topic("command") + ": retained commands are ignored"), 1)
        << puddle->log();
    EXPECT_EQ(puddle->count("remote: " + topic("set/rain.intensity") + ": retained commands are ignored"), 1)
        << puddle->log();
    EXPECT_EQ(puddle->count("retained commands are ignored"), 2) << puddle->log();

    // Clearing them (an empty retained message, passed on to subscribers) is neither applied nor an error.
    const std::size_t errors = client->received(topic("error")).size();
    client->publish(topic("command"), "", true);
    client->publish(topic("set/rain.intensity"), "", true);
    handled_after("0.8");
    EXPECT_EQ(client->received(topic("error")).size(), errors) << puddle->log();
    EXPECT_EQ(puddle->count("info: preset:"), 0) << puddle->log();
    EXPECT_EQ(puddle->stop(), 0);
    EXPECT_EQ(read_file(dir / "state.toml").find("0.9"), std::string::npos) << read_file(dir / "state.toml");
}

TEST_F(RemoteEndToEnd, NoBrokerIsOneWarningAndTheDisplayRuns) {
    const int port = free_port();
    dir.write("puddle.toml", remote_config(port));
    std::vector<std::string> args = puddle_args(dir);
    args.insert(args.end(), {"--stats", "1"});
    Running p(args, dir / "puddle.log");
    ASSERT_TRUE(p.wait_for("stats:", 3)) << p.log();  // four reports: frames go on
    EXPECT_EQ(p.count("cannot connect to the broker"), 1) << p.log();
    EXPECT_EQ(p.stop(), 0);
}

// Issue 33, item 5: the whole process, as `systemctl stop` sees it, with the broker's host dropping
// packets (it took 129 s, and systemd killed it).
TEST_F(RemoteEndToEnd, SigtermWhileTheBrokersHostDropsPacketsEndsAtOnce) {
    BlackholePort hole;
    dir.write("puddle.toml", remote_config(hole.port()));
    Running p(puddle_args(dir), dir / "puddle.log");
    ASSERT_TRUE(p.wait_for("started:")) << p.log();
    std::this_thread::sleep_for(std::chrono::seconds(1));  // inside the connect
    const double t0 = monotonic_seconds();
    EXPECT_EQ(p.stop(), 0) << p.log();
    EXPECT_LT(monotonic_seconds() - t0, 1.5) << p.log();
}

// The same with the broker's name lookup hanging (a DNS server that drops packets): libmosquitto looks the
// name up inside its connect, which no stop interrupts; the stop leaves it behind, says so, and exits.
TEST_F(RemoteEndToEnd, SigtermWhileTheBrokersNameLookupHangsEndsAtOnce) {
    dir.write("puddle.toml", remote_config(1883, "host = \"broker.hang.test\"\n"));
    Running p(puddle_args(dir), dir / "puddle.log", {"LD_PRELOAD=" PUDDLE_HANGING_NAME_LOOKUP});
    ASSERT_TRUE(p.wait_for("started:")) << p.log();
    std::this_thread::sleep_for(std::chrono::seconds(1));  // inside the lookup
    const double t0 = monotonic_seconds();
    EXPECT_EQ(p.stop(), 0) << p.log();
    EXPECT_LT(monotonic_seconds() - t0, 2.0) << p.log();
    EXPECT_EQ(p.count("broker.hang.test:1883: the network did not answer within 0.9 s"), 1) << p.log();
}

TEST_F(RemoteEndToEnd, LastWillSaysOfflineWhenKilled) {
    start_puddle();
    puddle->signal(SIGKILL);
    EXPECT_TRUE(client->wait_for(
        topic("availability"), [](auto& p) { return p == "offline"; }, 60));
}

}  // namespace
}  // namespace puddle::test
