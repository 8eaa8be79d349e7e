#pragma once
// An MQTT client (libmosquitto, MQTT 3.1.1) on its own network thread. The frame thread never waits
// for the network: it takes what arrived from a bounded inbox (drain: a swap, no allocation when
// nothing came) and leaves what it sends in a bounded outbox. The thread connects without blocking
// (mosquitto_connect_async: the TCP and TLS handshakes run in its loop, given up after
// connect_timeout_s), subscribes, publishes `online` retained on the availability topic (the last will,
// set before connecting, is `offline` retained) and, when the broker is missing, goes away or refuses
// the credentials, says so once and tries again with a growing delay (1 s doubling to 30 s); the
// display never notices. A connection taken over again and again (another client with the same id) is
// said once with its cause, then summarised. A stop never waits for the network beyond stop_limit_s (a host
// that drops packets, a name lookup with no DNS server): start, stop and the frames are never held by it.
// Messages beyond the rate limit (a burst of 40, then 20 a second) are held back, the newest per topic
// (a slider dragged in Home Assistant sends many values; the last is the one meant), and passed on as
// the limit allows; those they replace, and any beyond a full inbox or a full hold, are dropped and
// counted (dropped()), so a flood costs the frame loop nothing.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "remote/remote_request.hpp"
#include "util/result.hpp"

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
    // Seconds a connection attempt may take (TCP, TLS, CONNACK) before it is given up and tried again.
    static constexpr double connect_timeout_s = 15.0;
    // Seconds the destructor waits at most: for the broker to acknowledge what was queued (goodbye_s),
    // then for the network thread; one still inside a network call is left to end on its own.
    static constexpr double goodbye_s = 0.5;
    // A connection the broker closes within stable_s of making it, takeover_after times in a row with
    // every reconnect accepted, is taken over by another client with the same id (two screens cloned from
    // one image): said once with the cause and the fix, then summarised (util/recurring_fault.hpp); from
    // then on the reconnect delay grows until a connection holds stable_s.
    static constexpr double stable_s = 60.0;
    static constexpr int takeover_after = 3;
    static constexpr double stop_limit_s = 0.9;

    // Starts the network thread; nothing here touches the network. Errors: libmosquitto refuses the
    // options (a TLS file it cannot use).
    static Result<std::unique_ptr<MqttClient>> start(ClientOptions options);
    // Publishes `offline` on the availability topic, disconnects and ends the thread (stop_limit_s at
    // most, whatever the network does).
    ~MqttClient();
    MqttClient(const MqttClient&) = delete;
    MqttClient& operator=(const MqttClient&) = delete;

    // Frame thread: the messages that arrived since the last call, into `out` (cleared first; keep its
    // capacity at inbox_capacity and nothing allocates).
    void drain(std::vector<Inbound>& out);
    // Any thread: queued for the network thread; dropped when not connected or the outbox is full.
    void publish(std::string topic, std::string payload, bool retain);
    // Successful connections so far: a change means "publish everything retained again".
    std::uint64_t connections() const;
    bool connected() const;
    // Messages dropped (rate limit, full inbox) since the last call.
    std::uint64_t take_dropped();
    // Publishes not sent (not connected, full outbox) since start.
    std::uint64_t unsent() const;

private:
    // Everything the network thread uses (mqtt_client.cpp). Shared with the thread, so that a stop that
    // does not wait for it leaves nothing the thread still reads freed under it.
    struct Session;
    explicit MqttClient(std::shared_ptr<Session> session);

    std::shared_ptr<Session> session_;
    std::jthread thread_;
};

}  // namespace puddle::remote
