#include "app/logging.hpp"

#include <spdlog/pattern_formatter.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "util/valid_utf8.hpp"

namespace puddle::app {

namespace {

// "%*" in a pattern: the syslog priority of the message's level, as journald reads it from a stream.
class PriorityFlag : public spdlog::custom_flag_formatter {
public:
    void format(const spdlog::details::log_msg& msg, const std::tm&, spdlog::memory_buf_t& dest) override {
        char prefix[4] = {'<', '6', '>', '\0'};
        switch (msg.level) {
            case spdlog::level::trace:
            case spdlog::level::debug:
                prefix[1] = '7';
                break;
            case spdlog::level::info:
                prefix[1] = '6';
                break;
            case spdlog::level::warn:
                prefix[1] = '4';
                break;
            case spdlog::level::err:
                prefix[1] = '3';
                break;
            case spdlog::level::critical:
                prefix[1] = '2';
                break;
            default:
                break;
        }
        dest.append(prefix, prefix + 3);
    }
    std::unique_ptr<custom_flag_formatter> clone() const override { return std::make_unique<PriorityFlag>(); }
};

// "%~" in a pattern: the message as valid UTF-8. A line may quote bytes from anywhere (a payload from the
// broker, a file name); the journal, terminals and log shippers need UTF-8, so invalid bytes are U+FFFD.
class ValidUtf8Message : public spdlog::custom_flag_formatter {
public:
    void format(const spdlog::details::log_msg& msg, const std::tm&, spdlog::memory_buf_t& dest) override {
        append_valid_utf8(std::string_view(msg.payload.data(), msg.payload.size()), dest);
    }
    std::unique_ptr<custom_flag_formatter> clone() const override {
        return std::make_unique<ValidUtf8Message>();
    }
};

}  // namespace

LogStyle detect_log_style() {
    // systemd sets JOURNAL_STREAM to "device:inode" of the stream it connected; it only counts when
    // stderr is still that stream (not redirected by a wrapper).
    if (const char* js = std::getenv("JOURNAL_STREAM")) {
        struct stat st {};
        unsigned long long dev = 0, ino = 0;
        if (std::sscanf(js, "%llu:%llu", &dev, &ino) == 2 && fstat(STDERR_FILENO, &st) == 0 &&
            static_cast<unsigned long long>(st.st_dev) == dev &&
            static_cast<unsigned long long>(st.st_ino) == ino)
            return LogStyle::Journal;
    }
    return isatty(STDERR_FILENO) ? LogStyle::Terminal : LogStyle::Plain;
}

void setup_logging(LogStyle style) {
    std::shared_ptr<spdlog::logger> logger;
    auto formatter = std::make_unique<spdlog::pattern_formatter>();
    formatter->add_flag<ValidUtf8Message>('~');  // "%~", never "%v": see ValidUtf8Message
    switch (style) {
        case LogStyle::Terminal:
            logger = spdlog::stderr_color_mt("puddle");
            formatter->set_pattern("%^%l%$: %~");
            break;
        case LogStyle::Journal:
            logger = spdlog::stderr_logger_mt("puddle");
            formatter->add_flag<PriorityFlag>('*').set_pattern("%*%~");
            break;
        case LogStyle::Plain:
            logger = spdlog::stderr_logger_mt("puddle");
            formatter->set_pattern("%l: %~");
            break;
    }
    logger->set_formatter(std::move(formatter));
    logger->flush_on(spdlog::level::info);  // one line per event, visible at once in files and pipes
    spdlog::set_default_logger(logger);
}

}  // namespace puddle::app
