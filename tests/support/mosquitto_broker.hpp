#pragma once
// Debian's Mosquitto broker for the remote tests, started on a free loopback port and stopped at the end;
// and a small MQTT client (libmosquitto) that records what it receives. Without a config file Mosquitto
// 2 listens on loopback only; a test that needs TLS or passwords writes its own config.

#include <sys/types.h>

#include <condition_variable>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

struct mosquitto;

namespace puddle::test {

inline constexpr const char* mosquitto_path = "/usr/sbin/mosquitto";
// The message a test skips with when the broker is not installed.
inline constexpr const char* no_mosquitto = "mosquitto is not installed (apt-get install mosquitto)";
bool mosquitto_available();

// A TCP port on 127.0.0.1 that nothing listens on now.
int free_port();

class MosquittoBroker {
public:
    // `config`: the text of a mosquitto.conf (it names its own listener); empty: `-p PORT`, loopback only.
    explicit MosquittoBroker(int port = free_port(), std::string config = "");
    ~MosquittoBroker();
    MosquittoBroker(const MosquittoBroker&) = delete;
    MosquittoBroker& operator=(const MosquittoBroker&) = delete;

    // Starts it and waits (up to 10 s) until the port accepts connections.
    bool start();
    // SIGTERM, and waits for it to exit.
    void stop();
    // SIGSTOP: a broker that keeps its connections open and stops answering; SIGCONT: it goes on.
    void signal(int sig) const;
    int port() const { return port_; }
    bool running() const { return pid_ > 0; }
    std::string log() const;

private:
    int port_;
    std::string config_;
    std::filesystem::path dir_;
    pid_t pid_ = -1;
};

class MqttTestClient {
public:
    struct Options {
        int port = 0;
        std::string ca_file, username, password;
    };
    explicit MqttTestClient(Options options);
    ~MqttTestClient();
    MqttTestClient(const MqttTestClient&) = delete;
    MqttTestClient& operator=(const MqttTestClient&) = delete;

    bool connected() const { return connected_; }
    void subscribe(const std::string& pattern);
    void publish(const std::string& topic, const std::string& payload, bool retain = false);
    // Waits up to `timeout_s` until a message on `topic` satisfies `accept` (called with the client's lock
    // held: it must not call the client); returns its payload.
    std::optional<std::string> wait_for(const std::string& topic,
                                        const std::function<bool(const std::string&)>& accept = {},
                                        double timeout_s = 30);
    // Waits up to `timeout_s` until `topic` has had more than `seen` messages; returns the newest.
    std::optional<std::string> wait_for_more(const std::string& topic, std::size_t seen,
                                             double timeout_s = 30);
    // Every message received so far on `topic`, oldest first.
    std::vector<std::string> received(const std::string& topic);
    // The newest payload of every topic received so far.
    std::map<std::string, std::string> latest();
    void forget();

private:
    mosquitto* mosq_ = nullptr;
    mutable std::mutex mutex_;
    std::condition_variable arrived_;
    std::map<std::string, std::vector<std::string>> messages_;
    bool connected_ = false;
};

}  // namespace puddle::test
