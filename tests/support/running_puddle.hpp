#pragma once
// The puddle binary running in the background until stopped, its stdout and stderr in a log file: for
// end-to-end tests that change things under a running display (config edits, signals, resource limits).

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace puddle::test {

class Running {
public:
    // `environment`: NAME=value lines added to this process's environment (NOTIFY_SOCKET=..., say).
    Running(const std::vector<std::string>& args, std::filesystem::path log,
            const std::vector<std::string>& environment = {});
    ~Running();
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;

    // Waits (up to 60 s: llvmpipe on a busy CI machine is slow) until the log holds `text` more than
    // `after` times; false at once when the process has exited without it.
    bool wait_for(const std::string& text, int after = 0);
    // How many times the log holds `text`.
    int count(const std::string& text) const;
    void signal(int sig) const;
    // False once the process has exited.
    bool running();
    // SIGTERM, then its exit code (-1 when it did not exit normally, e.g. killed by a signal).
    int stop();
    std::string log() const;
    bool ok() const { return ok_; }
    pid_t pid() const { return pid_; }

private:
    std::filesystem::path log_;
    pid_t pid_ = -1;
    bool ok_ = false;
};

}  // namespace puddle::test
