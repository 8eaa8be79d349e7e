// The libgpiod 1.x backend (Debian 12 ships 1.6). Built instead of gpio_gpiod_v2.cpp when pkg-config
// finds libgpiod < 2.
#include <gpiod.h>
#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>

#include "io/gpio_backend.hpp"

namespace puddle::io {

namespace {

double seconds(const timespec& ts) {
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

class GpiodV1Line : public GpioLine {
public:
    GpiodV1Line(gpiod_chip* chip, gpiod_line* line)
        : chip_(chip), line_(line), fd_(gpiod_line_event_get_fd(line)) {}
    ~GpiodV1Line() override {
        gpiod_line_release(line_);
        gpiod_chip_close(chip_);
    }

    Result<bool> level() override {
        const int v = gpiod_line_get_value(line_);
        if (v < 0)
            return make_error(ExitCode::Runtime, "gpio: reading {}: {}",
                              gpiod_line_name(line_) ? gpiod_line_name(line_) : "line", std::strerror(errno));
        return v == 1;
    }

    Result<std::size_t> read_events(std::span<LineEvent> out) override {
        std::size_t n = 0;
        while (n < out.size()) {
            pollfd p{fd_, POLLIN, 0};
            const int ready = ::poll(&p, 1, 0);  // never wait: the frame loop must not block
            if (ready < 0 && errno == EINTR) continue;
            if (ready <= 0) break;
            if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
                return make_error(ExitCode::Runtime, "gpio: line {} is gone", gpiod_line_offset(line_));
            gpiod_line_event events[16];
            const unsigned want = static_cast<unsigned>(std::min<std::size_t>(16, out.size() - n));
            const int got = gpiod_line_event_read_fd_multiple(fd_, events, want);
            if (got < 0) {
                if (errno == EAGAIN || errno == EINTR) break;
                return make_error(ExitCode::Runtime, "gpio: line {}: {}", gpiod_line_offset(line_),
                                  std::strerror(errno));
            }
            for (int i = 0; i < got; ++i)
                out[n++] =
                    LineEvent{events[i].event_type == GPIOD_LINE_EVENT_RISING_EDGE, seconds(events[i].ts)};
            if (got < static_cast<int>(want)) break;
        }
        return n;
    }

private:
    gpiod_chip* chip_;
    gpiod_line* line_;
    int fd_;
};

class GpiodV1Backend : public GpioBackend {
public:
    std::string_view name() const override { return "libgpiod 1"; }

    Result<std::unique_ptr<GpioLine>> request(const LineRequest& r) override {
        errno = 0;
        gpiod_chip* chip = gpiod_chip_open_lookup(r.chip.c_str());
        if (!chip) return gpio_request_error(r, errno ? errno : ENOENT);
        gpiod_line* line = is_number(r.line)
                               ? gpiod_chip_get_line(chip, static_cast<unsigned>(std::stoul(r.line)))
                               : gpiod_chip_find_line(chip, r.line.c_str());
        if (!line) {
            const int err = errno ? errno : ENOENT;
            gpiod_chip_close(chip);
            return gpio_request_error(r, err);
        }
        int flags = r.active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
        switch (r.bias) {
            case params::LineBias::AsIs:
                break;
            case params::LineBias::PullUp:
                flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP;
                break;
            case params::LineBias::PullDown:
                flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_DOWN;
                break;
            case params::LineBias::Disabled:
                flags |= GPIOD_LINE_REQUEST_FLAG_BIAS_DISABLE;
                break;
        }
        const gpiod_line_request_config config{"puddle", GPIOD_LINE_REQUEST_EVENT_BOTH_EDGES, flags};
        if (gpiod_line_request(line, &config, 0) < 0) {
            const int err = errno;
            gpiod_chip_close(chip);
            return gpio_request_error(r, err);
        }
        std::unique_ptr<GpioLine> out = std::make_unique<GpiodV1Line>(chip, line);
        return out;
    }

    std::vector<GpioChipInfo> chips() override {
        std::vector<GpioChipInfo> out;
        for (const std::string& path : gpio_chip_paths()) {
            gpiod_chip* chip = gpiod_chip_open(path.c_str());
            if (!chip) {
                out.push_back({path, "", 0, std::strerror(errno)});
                continue;
            }
            out.push_back({gpiod_chip_name(chip), gpiod_chip_label(chip), gpiod_chip_num_lines(chip), ""});
            gpiod_chip_close(chip);
        }
        return out;
    }
};

}  // namespace

std::unique_ptr<GpioBackend> make_gpiod_backend() {
    return std::make_unique<GpiodV1Backend>();
}

}  // namespace puddle::io
