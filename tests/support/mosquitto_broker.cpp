#include "support/mosquitto_broker.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <mosquitto.h>
#include <netinet/in.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <optional>
#include <thread>

#include "support/test_support.hpp"

extern char** environ;

namespace puddle::test {

namespace {

bool accepts(int port) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const bool ok = connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
    close(fd);
    return ok;
}

}  // namespace

bool mosquitto_available() {
    return access(mosquitto_path, X_OK) == 0;
}

int free_port() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
    socklen_t len = sizeof a;
    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
    close(fd);
    return ntohs(a.sin_port);
}

MosquittoBroker::MosquittoBroker(int port, std::string config) : port_(port), config_(std::move(config)) {
    dir_ = std::filesystem::temp_directory_path() /
           ("puddle-broker-" + std::to_string(getpid()) + "-" + std::to_string(port_));
    std::filesystem::create_directories(dir_);
    start();
}

MosquittoBroker::~MosquittoBroker() {
    stop();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
}

bool MosquittoBroker::start() {
    if (pid_ > 0) return true;
    std::vector<std::string> args{mosquitto_path};
    if (config_.empty()) {
        args.insert(args.end(), {"-p", std::to_string(port_)});
    } else {
        std::ofstream(dir_ / "mosquitto.conf") << config_;
        args.insert(args.end(), {"-c", (dir_ / "mosquitto.conf").string()});
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log = (dir_ / "mosquitto.log").string();
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    const bool spawned = posix_spawn(&pid_, mosquitto_path, &actions, nullptr, argv.data(), environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
    if (!spawned) {
        pid_ = -1;
        return false;
    }
    for (int i = 0; i < 200; ++i) {
        if (accepts(port_)) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

void MosquittoBroker::stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGCONT);  // a stopped broker would hold SIGTERM
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
}

void MosquittoBroker::signal(int sig) const {
    if (pid_ > 0) kill(pid_, sig);
}

std::string MosquittoBroker::log() const {
    return read_file(dir_ / "mosquitto.log");
}

MqttTestClient::MqttTestClient(Options o) {
    mosquitto_lib_init();
    mosq_ = mosquitto_new(nullptr, true, this);
    if (!o.ca_file.empty()) mosquitto_tls_set(mosq_, o.ca_file.c_str(), nullptr, nullptr, nullptr, nullptr);
    if (!o.username.empty()) mosquitto_username_pw_set(mosq_, o.username.c_str(), o.password.c_str());
    mosquitto_message_callback_set(mosq_, [](mosquitto*, void* self, const mosquitto_message* m) {
        auto* c = static_cast<MqttTestClient*>(self);
        std::lock_guard lock(c->mutex_);
        c->messages_[m->topic].emplace_back(static_cast<const char*>(m->payload),
                                            static_cast<std::size_t>(m->payloadlen));
        c->arrived_.notify_all();
    });
    connected_ = mosquitto_connect(mosq_, "localhost", o.port, 30) == MOSQ_ERR_SUCCESS;
    mosquitto_loop_start(mosq_);
}

MqttTestClient::~MqttTestClient() {
    mosquitto_disconnect(mosq_);
    mosquitto_loop_stop(mosq_, true);
    mosquitto_destroy(mosq_);
}

void MqttTestClient::subscribe(const std::string& pattern) {
    mosquitto_subscribe(mosq_, nullptr, pattern.c_str(), 1);
}

void MqttTestClient::publish(const std::string& topic, const std::string& payload, bool retain) {
    mosquitto_publish(mosq_, nullptr, topic.c_str(), static_cast<int>(payload.size()), payload.data(), 1,
                      retain);
}

std::optional<std::string> MqttTestClient::wait_for(const std::string& topic,
                                                    const std::function<bool(const std::string&)>& accept,
                                                    double timeout_s) {
    std::unique_lock lock(mutex_);
    std::optional<std::string> found;
    arrived_.wait_for(lock, std::chrono::duration<double>(timeout_s), [&] {
        auto it = messages_.find(topic);
        if (it == messages_.end()) return false;
        for (const std::string& p : it->second)
            if (!accept || accept(p)) {
                found = p;
                return true;
            }
        return false;
    });
    return found;
}

std::optional<std::string> MqttTestClient::wait_for_more(const std::string& topic, std::size_t seen,
                                                         double timeout_s) {
    std::unique_lock lock(mutex_);
    const bool more = arrived_.wait_for(lock, std::chrono::duration<double>(timeout_s), [&] {
        auto it = messages_.find(topic);
        return it != messages_.end() && it->second.size() > seen;
    });
    if (!more) return std::nullopt;
    return messages_[topic].back();
}

std::vector<std::string> MqttTestClient::received(const std::string& topic) {
    std::lock_guard lock(mutex_);
    auto it = messages_.find(topic);
    return it == messages_.end() ? std::vector<std::string>{} : it->second;
}

std::map<std::string, std::string> MqttTestClient::latest() {
    std::lock_guard lock(mutex_);
    std::map<std::string, std::string> out;
    for (const auto& [topic, payloads] : messages_) out[topic] = payloads.back();
    return out;
}

void MqttTestClient::forget() {
    std::lock_guard lock(mutex_);
    messages_.clear();
}

}  // namespace puddle::test
