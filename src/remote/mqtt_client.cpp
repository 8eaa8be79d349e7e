#include "remote/mqtt_client.hpp"

#include <mosquitto.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstring>
#include <ctime>
#include <mutex>

#include "util/monotonic_clock.hpp"
#include "util/recurring_fault.hpp"
#include "util/worker_thread.hpp"

namespace puddle::remote {

namespace {

// mosquitto_lib_init() once per process, before the first client (it is not thread-safe itself).
void init_library() {
    static const int once = mosquitto_lib_init();
    (void)once;
}

std::string why(int rc) {
    if (rc == MOSQ_ERR_ERRNO) return std::strerror(errno);
    return mosquitto_strerror(rc);
}

}  // namespace

struct MqttClient::Session {
    explicit Session(ClientOptions o) : options(std::move(o)) { inbox.reserve(inbox_capacity); }
    ~Session() {
        if (mosq) mosquitto_destroy(mosq);
    }

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

    ClientOptions options;
    mosquitto* mosq = nullptr;
    std::mutex inbox_mutex;
    std::vector<Inbound> inbox;
    std::mutex outbox_mutex;
    std::vector<Outbound> outbox, sending;
    std::mutex wake_mutex;
    std::condition_variable_any wake;
    std::atomic<std::uint64_t> connections{0}, dropped{0}, unsent{0};
    std::atomic<bool> connected{false};
    // Set by the destructor: the thread logs nothing more (a thread left running may outlive the logger).
    std::atomic<bool> stopping{false};
    std::mutex finished_mutex;
    std::condition_variable finished_changed;
    bool finished = false;  // the thread has returned from run()

    // Network thread only from here.
    bool initialized = false;    // mosquitto_connect_async has been called (host, port and keepalive set)
    bool answered = false;       // the broker sent CONNACK on this attempt (accepting or refusing)
    double attempt_started = 0;  // monotonic seconds
    // QoS 1 messages sent since the last connection and not yet acknowledged. A clean stop waits for
    // them: libmosquitto keeps only 20 in flight, and the rest of a burst (the discovery configs, cleared
    // at a stop) would otherwise die with the connection.
    int unacknowledged = 0;
    bool outage_reported = false;
    // Connections the broker closed soon after making them (within stable_s), one after the other with
    // no failed attempt between: another client with our id takes the connection each time it
    // reconnects (MQTT 3.1.1 does not say so), and we take it back. The third is said with its cause.
    // A broker that restarts is told apart by the first try after a loss, 1 s later: it finds the broker
    // away (a restart that takes less, three times in a row, would pass for a takeover).
    double connected_at = 0;  // monotonic seconds
    bool held = false;        // this connection has lasted stable_s
    int short_in_a_row = 0;
    RecurringFault takeover;
    void on_lost(int rc);
    void on_held();
    double tokens = rate_burst, tokens_at = 0;
    std::vector<Inbound> held_back;  // the newest rate-limited message per topic
};

MqttClient::MqttClient(std::shared_ptr<Session> session) : session_(std::move(session)) {}

Result<std::unique_ptr<MqttClient>> MqttClient::start(ClientOptions options) {
    init_library();
    auto s = std::make_shared<Session>(std::move(options));
    const ClientOptions& o = s->options;
    s->mosq = mosquitto_new(o.client_id.c_str(), true, s.get());
    if (!s->mosq) return make_error(ExitCode::Runtime, "remote: mosquitto_new: {}", std::strerror(errno));
    auto fail = [&](const char* what, int rc) {
        return make_error(ExitCode::Config, "remote: {}:{}: {}: {}", o.host, o.port, what, why(rc));
    };
    if (!o.tls_ca.empty()) {
        const int rc = mosquitto_tls_set(s->mosq, o.tls_ca.c_str(), nullptr,
                                         o.tls_cert.empty() ? nullptr : o.tls_cert.c_str(),
                                         o.tls_key.empty() ? nullptr : o.tls_key.c_str(), nullptr);
        if (rc != MOSQ_ERR_SUCCESS) return fail("TLS files (remote.tls_ca, tls_cert, tls_key)", rc);
    }
    if (!o.username.empty()) {
        const int rc = mosquitto_username_pw_set(s->mosq, o.username.c_str(),
                                                 o.password.empty() ? nullptr : o.password.c_str());
        if (rc != MOSQ_ERR_SUCCESS) return fail("user name", rc);
    }
    // The last will, before connecting: the broker says `offline` for us when we vanish.
    if (const int rc = mosquitto_will_set(s->mosq, o.availability_topic.c_str(), 7, "offline", 1, true);
        rc != MOSQ_ERR_SUCCESS)
        return fail("last will", rc);
    mosquitto_connect_callback_set(s->mosq, Session::on_connect);
    mosquitto_message_callback_set(s->mosq, Session::on_message);
    mosquitto_publish_callback_set(s->mosq, Session::on_publish);
    std::unique_ptr<MqttClient> c(new MqttClient(s));
    // The thread holds the session too: when the destructor leaves it behind, it frees it on leaving.
    c->thread_ = start_worker_thread([s](std::stop_token stop) {
        s->run(stop);
        std::lock_guard lock(s->finished_mutex);
        s->finished = true;
        s->finished_changed.notify_all();
    });
    return c;
}

MqttClient::~MqttClient() {
    thread_.request_stop();  // wakes wait() too (it waits on the stop token)
    std::unique_lock lock(session_->finished_mutex);
    const bool ended = session_->finished_changed.wait_for(lock, std::chrono::duration<double>(stop_limit_s),
                                                           [&] { return session_->finished; });
    lock.unlock();
    if (ended) {
        thread_.join();
        return;
    }
    // Inside a call that does not return at our asking (a name lookup): it ends on its own, later, and
    // frees the session then; the process may well have exited by then.
    spdlog::warn("remote: {}:{}: the network did not answer within {:g} s; stopping without waiting for it",
                 session_->options.host, session_->options.port, stop_limit_s);
    session_->stopping = true;
    thread_.detach();
}

void MqttClient::drain(std::vector<Inbound>& out) {
    out.clear();
    Session& s = *session_;
    std::lock_guard lock(s.inbox_mutex);
    if (s.inbox.empty()) return;
    out.swap(s.inbox);
    if (s.inbox.capacity() < inbox_capacity) s.inbox.reserve(inbox_capacity);
}

void MqttClient::publish(std::string topic, std::string payload, bool retain) {
    Session& s = *session_;
    {
        std::lock_guard lock(s.outbox_mutex);
        if (!s.connected || s.outbox.size() >= outbox_capacity) {
            ++s.unsent;
            return;
        }
        s.outbox.push_back({std::move(topic), std::move(payload), retain});
    }
    s.wake.notify_all();
}

std::uint64_t MqttClient::connections() const {
    return session_->connections.load();
}
bool MqttClient::connected() const {
    return session_->connected.load();
}
std::uint64_t MqttClient::take_dropped() {
    return session_->dropped.exchange(0);
}
std::uint64_t MqttClient::unsent() const {
    return session_->unsent.load();
}

void MqttClient::Session::warn_once(const std::string& line) {
    if (stopping) return;
    if (outage_reported) {
        spdlog::debug("{}", line);
        return;
    }
    outage_reported = true;
    spdlog::warn("{}; retrying in the background, the display runs on", line);
}

void MqttClient::Session::on_connect(mosquitto*, void* p, int rc) {
    auto* self = static_cast<Session*>(p);
    self->answered = true;
    if (rc != 0) {  // CONNACK refused: a wrong password, a client id the broker bans...
        self->warn_once(fmt::format("remote: {}:{}: the broker refused the connection: {}",
                                    self->options.host, self->options.port, mosquitto_connack_string(rc)));
        return;
    }
    for (const std::string& topic : self->options.subscriptions)
        mosquitto_subscribe(self->mosq, nullptr, topic.c_str(), 1);
    self->unacknowledged = 0;  // a new session: what was in flight on the old one is not coming back
    self->send_qos1(self->options.availability_topic, "online", 6, true);
    // While connections are being taken over, each reconnect is not news (the summary counts them).
    if (!self->stopping)
        spdlog::log(self->takeover.active() ? spdlog::level::debug : spdlog::level::info,
                    "remote: connected to {}:{} as {}", self->options.host, self->options.port,
                    self->options.client_id);
    self->outage_reported = false;
    self->connected_at = monotonic_seconds();
    self->held = false;
    self->connected = true;
    ++self->connections;
}

void MqttClient::Session::on_publish(mosquitto*, void* p, int) {
    auto* self = static_cast<Session*>(p);
    self->unacknowledged = std::max(self->unacknowledged - 1, 0);
}

int MqttClient::Session::send_qos1(const std::string& topic, const void* payload, std::size_t size,
                                   bool retain) {
    const int rc =
        mosquitto_publish(mosq, nullptr, topic.c_str(), static_cast<int>(size), payload, 1, retain);
    if (rc == MOSQ_ERR_SUCCESS) ++unacknowledged;
    return rc;
}

void MqttClient::Session::on_message(mosquitto*, void* p, const mosquitto_message* m) {
    auto* self = static_cast<Session*>(p);
    const auto size = static_cast<std::size_t>(std::max(0, m->payloadlen));
    Inbound in{m->topic ? m->topic : "", {}, size, m->retain};
    if (size <= max_payload_bytes && m->payload)
        in.payload.assign(static_cast<const char*>(m->payload), size);
    // The rate limit: a token bucket, refilled at rate_per_second up to rate_burst. Over the limit, the
    // message waits in held_back, replacing an older one of the same topic.
    self->refill_tokens();
    if (self->tokens < 1.0 || !self->held_back.empty()) {
        for (Inbound& h : self->held_back)
            if (h.topic == in.topic) {
                h = std::move(in);
                ++self->dropped;  // the value it replaced
                return;
            }
        if (self->held_back.size() >= inbox_capacity) {
            ++self->dropped;
            return;
        }
        self->held_back.push_back(std::move(in));
        self->release_held();
        return;
    }
    self->tokens -= 1.0;
    self->deliver(std::move(in));
}

void MqttClient::Session::refill_tokens() {
    const double now = monotonic_seconds();
    tokens = std::min(rate_burst, tokens + (now - tokens_at) * rate_per_second);
    tokens_at = now;
}

void MqttClient::Session::release_held() {
    refill_tokens();
    std::size_t released = 0;
    while (released < held_back.size() && tokens >= 1.0) {
        tokens -= 1.0;
        deliver(std::move(held_back[released++]));
    }
    held_back.erase(held_back.begin(), held_back.begin() + static_cast<std::ptrdiff_t>(released));
}

void MqttClient::Session::deliver(Inbound in) {
    std::lock_guard lock(inbox_mutex);
    if (inbox.size() >= inbox_capacity) {
        ++dropped;
        return;
    }
    inbox.push_back(std::move(in));
}

// Starts an attempt without waiting for it (the name lookup aside): the TCP connect, the TLS handshake
// and CONNACK come in mosquitto_loop.
bool MqttClient::Session::connect_once() {
    const int rc =
        initialized ? mosquitto_reconnect_async(mosq)
                    : mosquitto_connect_async(mosq, options.host.c_str(), options.port, options.keepalive_s);
    initialized = true;
    answered = false;
    attempt_started = monotonic_seconds();
    if (rc != MOSQ_ERR_SUCCESS) {
        short_in_a_row = 0;  // the broker itself is away (restarting): not a takeover
        warn_once(fmt::format("remote: {}:{}: cannot connect to the broker: {}", options.host, options.port,
                              why(rc)));
        return false;
    }
    return true;
}

void MqttClient::Session::flush_outbox() {
    {
        std::lock_guard lock(outbox_mutex);
        sending.swap(outbox);
    }
    for (const Outbound& o : sending)
        if (send_qos1(o.topic, o.payload.data(), o.payload.size(), o.retain) != MOSQ_ERR_SUCCESS) ++unsent;
    sending.clear();
}

void MqttClient::Session::wait(std::stop_token& stop, double seconds) {
    std::unique_lock lock(wake_mutex);
    wake.wait_for(lock, stop, std::chrono::duration<double>(seconds), [] { return false; });
}

namespace {

// "13:05:02", local time.
std::string clock_time(double wall) {
    const auto t = static_cast<std::time_t>(wall);
    std::tm local{};
    localtime_r(&t, &local);
    char text[16];
    std::strftime(text, sizeof text, "%H:%M:%S", &local);
    return text;
}

double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

void MqttClient::Session::on_lost(int rc) {
    connected = false;
    const double now = monotonic_seconds();
    if (now - connected_at >= stable_s || ++short_in_a_row < takeover_after) {
        if (now - connected_at >= stable_s) short_in_a_row = 0;
        warn_once(fmt::format("remote: {}:{}: lost the broker: {}", options.host, options.port, why(rc)));
        return;
    }
    const auto r = takeover.occurred(now, wall_seconds());
    if (stopping || r.say == RecurringFault::Say::Nothing) return;
    if (r.say == RecurringFault::Say::Full) {
        spdlog::warn(
            "remote: {}:{}: another client with id {} keeps taking the connection (the broker closed it {} "
            "times "
            "in a row within {:g} s of accepting it, and took each reconnect at once): two screens with one "
            "client id, from a cloned /etc/machine-id? Give each screen its own remote.client_id and "
            "remote.prefix, or a new machine id (sudo rm /etc/machine-id && sudo systemd-machine-id-setup, "
            "then "
            "reboot). Said once, then summarised; retrying with a growing delay (up to {:g} s)",
            options.host, options.port, options.client_id, short_in_a_row, stable_s, options.max_backoff_s);
        return;
    }
    spdlog::warn(
        "remote: {}:{}: the connection (client id {}) was taken over {} more times since {}, {} in all",
        options.host, options.port, options.client_id, r.since_said, clock_time(r.said_wall), r.total);
}

void MqttClient::Session::on_held() {
    held = true;
    short_in_a_row = 0;
    const double last = takeover.last_wall();
    if (const std::uint64_t total = takeover.clear(); total && !stopping)
        spdlog::info(
            "remote: {}:{}: the connection has held for {:g} s: taken over {} times in all, the last "
            "at {}",
            options.host, options.port, stable_s, total, clock_time(last));
}

void MqttClient::Session::run(std::stop_token stop) {
    double backoff = 1.0;
    bool connecting = true;
    while (!stop.stop_requested()) {
        if (connecting) {
            if (!connect_once()) {
                wait(stop, backoff);
                backoff = std::min(options.max_backoff_s, backoff * 2);
                continue;
            }
            connecting = false;
        }
        flush_outbox();
        int rc = mosquitto_loop(mosq, 50, 1);
        release_held();  // held messages go on as the rate limit refills, even when nothing new arrives
        // The delay starts again at 1 s on connecting; while the connection is being taken over, only once
        // one has held (the reconnects back off like failed attempts).
        if (connected && !takeover.active()) backoff = 1.0;
        if (connected && !held && monotonic_seconds() - connected_at >= stable_s) {
            on_held();
            backoff = 1.0;
        }
        // A host that drops packets never answers the connect: given up, then tried again.
        if (rc == MOSQ_ERR_SUCCESS && !answered && monotonic_seconds() - attempt_started > connect_timeout_s)
            rc = MOSQ_ERR_TIMEOUT;
        if (rc != MOSQ_ERR_SUCCESS) {
            if (connected) {
                on_lost(rc);
            } else if (answered) {
                short_in_a_row = 0;
                warn_once(fmt::format("remote: {}:{}: the broker closed the connection: {}", options.host,
                                      options.port, why(rc)));
            } else {
                short_in_a_row = 0;
                warn_once(fmt::format(
                    "remote: {}:{}: cannot connect to the broker: {}", options.host, options.port,
                    rc == MOSQ_ERR_TIMEOUT ? fmt::format("no answer within {:g} s", connect_timeout_s)
                                           : why(rc)));
            }
            connecting = true;
            wait(stop, backoff);
            backoff = std::min(options.max_backoff_s, backoff * 2);
        }
    }
    if (connected) {  // a clean goodbye: what is queued, then `offline` (the will is only for vanishing)
        flush_outbox();
        send_qos1(options.availability_topic, "offline", 7, true);
        // Until the broker has acknowledged all of it (a broker that stopped answering: goodbye_s at most).
        const double give_up = monotonic_seconds() + goodbye_s;
        while (monotonic_seconds() < give_up) {
            if (mosquitto_loop(mosq, 20, 1) != MOSQ_ERR_SUCCESS) break;  // the connection is gone
            if (unacknowledged == 0 && !mosquitto_want_write(mosq)) break;
        }
        mosquitto_disconnect(mosq);
        mosquitto_loop(mosq, 20, 1);
        connected = false;
    }
}

}  // namespace puddle::remote
