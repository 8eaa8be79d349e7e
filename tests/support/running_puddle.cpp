#include "support/running_puddle.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/test_support.hpp"

extern char** environ;

namespace puddle::test {

Running::Running(const std::vector<std::string>& args, std::filesystem::path log,
                 const std::vector<std::string>& environment)
    : log_(std::move(log)) {
    std::vector<std::string> all{PUDDLE_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env(environment);
    for (char** e = environ; *e; ++e) env.emplace_back(*e);
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    ok_ = posix_spawn(&pid_, PUDDLE_BINARY, &actions, nullptr, argv.data(), envp.data()) == 0;
    posix_spawn_file_actions_destroy(&actions);
}

Running::~Running() {
    if (pid_ > 0) stop();
}

bool Running::wait_for(const std::string& text, int after) {
    for (int i = 0; i < 600; ++i) {
        if (count(text) > after) return true;
        if (int status = 0; ::waitpid(pid_, &status, WNOHANG) == pid_) {  // it exited: no use waiting
            pid_ = -1;
            return count(text) > after;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
}

int Running::count(const std::string& text) const {
    const std::string log = read_file(log_);
    int n = 0;
    for (auto at = log.find(text); at != std::string::npos; at = log.find(text, at + 1)) ++n;
    return n;
}

void Running::signal(int sig) const {
    ::kill(pid_, sig);
}

bool Running::running() {
    if (pid_ <= 0) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) return true;
    pid_ = -1;
    return false;
}

int Running::stop() {
    if (pid_ <= 0) return -1;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string Running::log() const {
    return read_file(log_);
}

}  // namespace puddle::test
