// The MQTT client (remote/mqtt_client.hpp) against a real Mosquitto: what is queued before a clean stop
// reaches the broker, however much of it there is.
#include "remote/mqtt_client.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "support/mosquitto_broker.hpp"

namespace puddle::test {
namespace {

// libmosquitto keeps 20 QoS 1 messages in flight and queues the rest until the broker acknowledges
// some; a stop that only waited for the socket to drain dropped the rest with the connection (seen as
// discovery configs left retained after remote.enabled = false cleared them).
TEST(MqttClientStop, ABurstQueuedJustBeforeTheStopAllReachesTheBroker) {
    if (!mosquitto_available()) GTEST_SKIP() << no_mosquitto;
    MosquittoBroker broker;
    ASSERT_TRUE(broker.start()) << broker.log();
    auto client = remote::MqttClient::start({.host = "127.0.0.1",
                                             .port = broker.port(),
                                             .client_id = "burst",
                                             .availability_topic = "burst/status"});
    ASSERT_TRUE(client) << client.error().message;
    for (int i = 0; i < 1000 && !(*client)->connected(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE((*client)->connected());

    constexpr int burst = 300;
    for (int i = 0; i < burst; ++i) (*client)->publish(fmt::format("burst/{}", i), "kept", true);
    client->reset();  // the clean stop, at once
    EXPECT_EQ(client->get(), nullptr);

    MqttTestClient fresh({.port = broker.port()});
    fresh.subscribe("burst/#");
    ASSERT_TRUE(fresh.wait_for(
        "burst/status", [](const std::string& p) { return p == "offline"; }, 10))
        << "the goodbye comes after the burst";
    ASSERT_TRUE(fresh.wait_for(fmt::format("burst/{}", burst - 1), {}, 10));
    int retained = 0;
    for (const auto& [topic, payload] : fresh.latest()) retained += payload == "kept";
    EXPECT_EQ(retained, burst);
}

}  // namespace
}  // namespace puddle::test
