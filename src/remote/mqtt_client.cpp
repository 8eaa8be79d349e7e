#include "remote/mqtt_client.hpp"

#include <mosquitto.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstring>

#include "util/monotonic_clock.hpp"
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

MqttClient::MqttClient(ClientOptions options) : options_(std::move(options)) {
    inbox_.reserve(inbox_capacity);
}

Result<std::unique_ptr<MqttClient>> MqttClient::start(ClientOptions options) {
    init_library();
    std::unique_ptr<MqttClient> c(new MqttClient(std::move(options)));
    const ClientOptions& o = c->options_;
    c->mosq_ = mosquitto_new(o.client_id.c_str(), true, c.get());
    if (!c->mosq_) return make_error(ExitCode::Runtime, "remote: mosquitto_new: {}", std::strerror(errno));
    auto fail = [&](const char* what, int rc) {
        return make_error(ExitCode::Config, "remote: {}:{}: {}: {}", o.host, o.port, what, why(rc));
    };
    if (!o.tls_ca.empty()) {
        const int rc = mosquitto_tls_set(c->mosq_, o.tls_ca.c_str(), nullptr,
                                         o.tls_cert.empty() ? nullptr : o.tls_cert.c_str(),
                                         o.tls_key.empty() ? nullptr : o.tls_key.c_str(), nullptr);
        if (rc != MOSQ_ERR_SUCCESS) return fail("TLS files (remote.tls_ca, tls_cert, tls_key)", rc);
    }
    if (!o.username.empty()) {
        const int rc = mosquitto_username_pw_set(c->mosq_, o.username.c_str(),
                                                 o.password.empty() ? nullptr : o.password.c_str());
        if (rc != MOSQ_ERR_SUCCESS) return fail("user name", rc);
    }
    // The last will, before connecting: the broker says `offline` for us when we vanish.
    if (const int rc = mosquitto_will_set(c->mosq_, o.availability_topic.c_str(), 7, "offline", 1, true);
        rc != MOSQ_ERR_SUCCESS)
        return fail("last will", rc);
    mosquitto_connect_callback_set(c->mosq_, on_connect);
    mosquitto_message_callback_set(c->mosq_, on_message);
    mosquitto_publish_callback_set(c->mosq_, on_publish);
    MqttClient* self = c.get();
    c->thread_ = start_worker_thread([self](std::stop_token stop) { self->run(stop); });
    return c;
}

MqttClient::~MqttClient() {
    thread_.request_stop();
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    if (mosq_) mosquitto_destroy(mosq_);
}

void MqttClient::drain(std::vector<Inbound>& out) {
    out.clear();
    std::lock_guard lock(inbox_mutex_);
    if (inbox_.empty()) return;
    out.swap(inbox_);
    if (inbox_.capacity() < inbox_capacity) inbox_.reserve(inbox_capacity);
}

void MqttClient::publish(std::string topic, std::string payload, bool retain) {
    {
        std::lock_guard lock(outbox_mutex_);
        if (!connected_ || outbox_.size() >= outbox_capacity) {
            ++unsent_;
            return;
        }
        outbox_.push_back({std::move(topic), std::move(payload), retain});
    }
    wake_.notify_all();
}

void MqttClient::warn_once(const std::string& line) {
    if (outage_reported_) {
        spdlog::debug("{}", line);
        return;
    }
    outage_reported_ = true;
    spdlog::warn("{}; retrying in the background, the display runs on", line);
}

void MqttClient::on_connect(mosquitto*, void* p, int rc) {
    auto* self = static_cast<MqttClient*>(p);
    if (rc != 0) {  // CONNACK refused: a wrong password, a client id the broker bans...
        self->warn_once(fmt::format("remote: {}:{}: the broker refused the connection: {}",
                                    self->options_.host, self->options_.port, mosquitto_connack_string(rc)));
        return;
    }
    for (const std::string& topic : self->options_.subscriptions)
        mosquitto_subscribe(self->mosq_, nullptr, topic.c_str(), 1);
    self->unacknowledged_ = 0;  // a new session: what was in flight on the old one is not coming back
    self->send_qos1(self->options_.availability_topic, "online", 6, true);
    spdlog::info("remote: connected to {}:{} as {}", self->options_.host, self->options_.port,
                 self->options_.client_id);
    self->outage_reported_ = false;
    self->connected_ = true;
    ++self->connections_;
}

void MqttClient::on_publish(mosquitto*, void* p, int) {
    auto* self = static_cast<MqttClient*>(p);
    self->unacknowledged_ = std::max(self->unacknowledged_ - 1, 0);
}

int MqttClient::send_qos1(const std::string& topic, const void* payload, std::size_t size, bool retain) {
    const int rc =
        mosquitto_publish(mosq_, nullptr, topic.c_str(), static_cast<int>(size), payload, 1, retain);
    if (rc == MOSQ_ERR_SUCCESS) ++unacknowledged_;
    return rc;
}

void MqttClient::on_message(mosquitto*, void* p, const mosquitto_message* m) {
    auto* self = static_cast<MqttClient*>(p);
    const auto size = static_cast<std::size_t>(std::max(0, m->payloadlen));
    Inbound in{m->topic ? m->topic : "", {}, size, m->retain};
    if (size <= max_payload_bytes && m->payload)
        in.payload.assign(static_cast<const char*>(m->payload), size);
    // The rate limit: a token bucket, refilled at rate_per_second up to rate_burst. Over the limit, the
    // message waits in held_, replacing an older one of the same topic.
    self->refill_tokens();
    if (self->tokens_ < 1.0 || !self->held_.empty()) {
        for (Inbound& held : self->held_)
            if (held.topic == in.topic) {
                held = std::move(in);
                ++self->dropped_;  // the value it replaced
                return;
            }
        if (self->held_.size() >= inbox_capacity) {
            ++self->dropped_;
            return;
        }
        self->held_.push_back(std::move(in));
        self->release_held();
        return;
    }
    self->tokens_ -= 1.0;
    self->deliver(std::move(in));
}

void MqttClient::refill_tokens() {
    const double now = monotonic_seconds();
    tokens_ = std::min(rate_burst, tokens_ + (now - tokens_at_) * rate_per_second);
    tokens_at_ = now;
}

void MqttClient::release_held() {
    refill_tokens();
    std::size_t released = 0;
    while (released < held_.size() && tokens_ >= 1.0) {
        tokens_ -= 1.0;
        deliver(std::move(held_[released++]));
    }
    held_.erase(held_.begin(), held_.begin() + static_cast<std::ptrdiff_t>(released));
}

void MqttClient::deliver(Inbound in) {
    std::lock_guard lock(inbox_mutex_);
    if (inbox_.size() >= inbox_capacity) {
        ++dropped_;
        return;
    }
    inbox_.push_back(std::move(in));
}

bool MqttClient::connect_once() {
    const int rc = connections_ == 0 && !socket_open_
                       ? mosquitto_connect(mosq_, options_.host.c_str(), options_.port, options_.keepalive_s)
                       : mosquitto_reconnect(mosq_);
    if (rc != MOSQ_ERR_SUCCESS) {
        warn_once(fmt::format("remote: {}:{}: cannot connect to the broker: {}", options_.host, options_.port,
                              why(rc)));
        return false;
    }
    socket_open_ = true;
    return true;
}

void MqttClient::flush_outbox() {
    {
        std::lock_guard lock(outbox_mutex_);
        sending_.swap(outbox_);
    }
    for (const Outbound& o : sending_)
        if (send_qos1(o.topic, o.payload.data(), o.payload.size(), o.retain) != MOSQ_ERR_SUCCESS) ++unsent_;
    sending_.clear();
}

void MqttClient::wait(std::stop_token& stop, double seconds) {
    std::unique_lock lock(wake_mutex_);
    wake_.wait_for(lock, stop, std::chrono::duration<double>(seconds), [] { return false; });
}

void MqttClient::run(std::stop_token stop) {
    double backoff = 1.0;
    bool connecting = true;  // the first attempt uses mosquitto_connect
    while (!stop.stop_requested()) {
        if (connecting) {
            if (!connect_once()) {
                wait(stop, backoff);
                backoff = std::min(options_.max_backoff_s, backoff * 2);
                continue;
            }
            connecting = false;
        }
        flush_outbox();
        const int rc = mosquitto_loop(mosq_, 50, 1);
        release_held();  // held messages go on as the rate limit refills, even when nothing new arrives
        if (connected_) backoff = 1.0;
        if (rc != MOSQ_ERR_SUCCESS) {
            if (connected_) {
                connected_ = false;
                warn_once(
                    fmt::format("remote: {}:{}: lost the broker: {}", options_.host, options_.port, why(rc)));
            } else {
                warn_once(fmt::format("remote: {}:{}: the broker closed the connection: {}", options_.host,
                                      options_.port, why(rc)));
            }
            connecting = true;
            wait(stop, backoff);
            backoff = std::min(options_.max_backoff_s, backoff * 2);
        }
    }
    if (connected_) {  // a clean goodbye: what is queued, then `offline` (the will is only for vanishing)
        flush_outbox();
        send_qos1(options_.availability_topic, "offline", 7, true);
        // Until the broker has acknowledged all of it (a broker that stopped answering: 3 s at most).
        const double give_up = monotonic_seconds() + 3.0;
        while (monotonic_seconds() < give_up) {
            if (mosquitto_loop(mosq_, 20, 1) != MOSQ_ERR_SUCCESS) break;  // the connection is gone
            if (unacknowledged_ == 0 && !mosquitto_want_write(mosq_)) break;
        }
        mosquitto_disconnect(mosq_);
        mosquitto_loop(mosq_, 20, 1);
        connected_ = false;
    }
}

}  // namespace puddle::remote
