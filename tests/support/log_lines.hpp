#pragma once
// The log lines at or above a level while it lives (a spdlog sink on the default logger), so a test can
// count what was said: "logged once, not once a frame".

#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <memory>
#include <string>

namespace puddle::test {

class LogLines {
public:
    explicit LogLines(spdlog::level::level_enum level)
        : sink_(std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64)) {
        sink_->set_level(level);
        spdlog::default_logger()->sinks().push_back(sink_);
    }
    ~LogLines() {
        auto& sinks = spdlog::default_logger()->sinks();
        sinks.erase(std::remove(sinks.begin(), sinks.end(), sink_), sinks.end());
    }
    LogLines(const LogLines&) = delete;
    LogLines& operator=(const LogLines&) = delete;
    // Lines (of the newest 64) that contain `part`.
    long count(const std::string& part) const {
        const auto lines = sink_->last_formatted();
        return std::count_if(lines.begin(), lines.end(),
                             [&](const std::string& l) { return l.find(part) != std::string::npos; });
    }

private:
    std::shared_ptr<spdlog::sinks::ringbuffer_sink_mt> sink_;
};

}  // namespace puddle::test
