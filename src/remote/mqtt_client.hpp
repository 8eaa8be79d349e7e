#pragma once
// An MQTT client (libmosquitto, MQTT 3.1.1) on its own network thread. The frame thread never waits
// for the network: it takes what arrived from a bounded inbox (drain: a swap, no allocation when
// nothing came) and leaves what it sends in a bounded outbox. The thread connects, subscribes, publishes
// `online` retained on the availability topic (the last will, set before connecting, is `offline`
// retained) and, when the broker is missing, goes away or refuses the credentials, says so once and
// tries again with a growing delay (1 s doubling to 30 s); the display never notices.
// Messages beyond the rate limit (a burst of 40, then 20 a second) are held back, the newest per topic
// (a slider dragged in Home Assistant sends many values; the last is the one meant), and passed on as
// the limit allows; those they replace, and any beyond a full inbox or a full hold, are dropped and
// counted (dropped()), so a flood costs the frame loop nothing.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "remote/remote_request.hpp"
#include "util/result.hpp"

struct mosquitto;
struct mosquitto_message;

namespace puddle::remote {

struct ClientOptions {
    std::string host;
    int port = 1883;
    std::string client_id;
    int keepalive_s = 30;
    std::string tls_ca, tls_cert, tls_key;
    std::string username, password;
    std::string availability_topic;          // online / offline (the will)
    std::vector<std::string> subscriptions;  // subscribed again on every connect
    double max_backoff_s = 30.0;
};

struct Outbound {
    std::string topic;
    std::string payload;
    bool retain = false;
};

class MqttClient {
public:
    static constexpr std::size_t inbox_capacity = 64;
    static constexpr std::size_t outbox_capacity = 2048;  // one state topic per parameter fits, twice over
    static constexpr double rate_per_second = 20.0;
    static constexpr double rate_burst = 40.0;

    // Starts the network thread. Errors: libmosquitto refuses the options (a TLS file it cannot use).
    static Result<std::unique_ptr<MqttClient>> start(ClientOptions options);
    // Publishes `offline` on the availability topic, disconnects and joins the thread.
    ~MqttClient();
    MqttClient(const MqttClient&) = delete;
    MqttClient& operator=(const MqttClient&) = delete;

    // Frame thread: the messages that arrived since the last call, into `out` (cleared first; keep its
    // capacity at inbox_capacity and nothing allocates).
    void drain(std::vector<Inbound>& out);
    // Any thread: queued for the network thread; dropped when not connected or the outbox is full.
    void publish(std::string topic, std::string payload, bool retain);
    // Successful connections so far: a change means "publish everything retained again".
    std::uint64_t connections() const { return connections_.load(); }
    bool connected() const { return connected_.load(); }
    // Messages dropped (rate limit, full inbox) since the last call.
    std::uint64_t take_dropped() { return dropped_.exchange(0); }
    // Publishes not sent (not connected, full outbox) since start.
    std::uint64_t unsent() const { return unsent_.load(); }

private:
    explicit MqttClient(ClientOptions options);
    void run(std::stop_token stop);
    bool connect_once();
    void flush_outbox();
    // Refills the rate limit's tokens; passes held messages on while there are tokens.
    void release_held();
    void refill_tokens();
    void deliver(Inbound in);
    void wait(std::stop_token& stop, double seconds);
    void warn_once(const std::string& line);
    // mosquitto_publish at QoS 1 (network thread), counted until the broker's PUBACK (on_publish).
    int send_qos1(const std::string& topic, const void* payload, std::size_t size, bool retain);
    static void on_connect(mosquitto*, void* self, int rc);
    static void on_message(mosquitto*, void* self, const mosquitto_message* m);
    static void on_publish(mosquitto*, void* self, int mid);

    ClientOptions options_;
    mosquitto* mosq_ = nullptr;
    std::mutex inbox_mutex_;
    std::vector<Inbound> inbox_;
    std::mutex outbox_mutex_;
    std::vector<Outbound> outbox_, sending_;
    std::mutex wake_mutex_;
    std::condition_variable_any wake_;
    std::atomic<std::uint64_t> connections_{0}, dropped_{0}, unsent_{0};
    std::atomic<bool> connected_{false};
    bool socket_open_ = false;  // network thread only
    // Network thread only: QoS 1 messages sent since the last connection and not yet acknowledged. A clean
    // stop waits for them: libmosquitto keeps only 20 in flight, and the rest of a burst (the discovery
    // configs, cleared at a stop) would otherwise die with the connection.
    int unacknowledged_ = 0;
    bool outage_reported_ = false;
    double tokens_ = rate_burst, tokens_at_ = 0;
    std::vector<Inbound> held_;  // network thread only: the newest rate-limited message per topic
    std::jthread thread_;        // last: joined before the members it uses die
};

}  // namespace puddle::remote
