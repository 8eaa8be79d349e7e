// The libgpiod 2.x backend. Built instead of gpio_gpiod_v1.cpp when pkg-config finds libgpiod >= 2
// (Debian 13, Raspberry Pi OS trixie). Debian 12 has only 1.6, so CI here compiles the v1 file.
#include <gpiod.h>
#include <poll.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

#include "io/gpio_backend.hpp"

namespace puddle::io {

namespace {

// Owners for libgpiod's objects, so every early return frees what it made.
template <typename T, void (*Free)(T*)>
struct Deleter {
    void operator()(T* p) const { Free(p); }
};
using ChipPtr = std::unique_ptr<gpiod_chip, Deleter<gpiod_chip, gpiod_chip_close>>;
using SettingsPtr =
    std::unique_ptr<gpiod_line_settings, Deleter<gpiod_line_settings, gpiod_line_settings_free>>;
using LineConfigPtr = std::unique_ptr<gpiod_line_config, Deleter<gpiod_line_config, gpiod_line_config_free>>;
using RequestConfigPtr =
    std::unique_ptr<gpiod_request_config, Deleter<gpiod_request_config, gpiod_request_config_free>>;
using RequestPtr =
    std::unique_ptr<gpiod_line_request, Deleter<gpiod_line_request, gpiod_line_request_release>>;
using BufferPtr =
    std::unique_ptr<gpiod_edge_event_buffer, Deleter<gpiod_edge_event_buffer, gpiod_edge_event_buffer_free>>;
using InfoPtr = std::unique_ptr<gpiod_chip_info, Deleter<gpiod_chip_info, gpiod_chip_info_free>>;

// v2 opens chips by path only: resolve a name, a number or a label the way v1's open_lookup did.
ChipPtr open_chip(const std::string& chip) {
    if (chip.starts_with("/")) return ChipPtr(gpiod_chip_open(chip.c_str()));
    if (is_number(chip)) return ChipPtr(gpiod_chip_open(("/dev/gpiochip" + chip).c_str()));
    if (chip.starts_with("gpiochip")) return ChipPtr(gpiod_chip_open(("/dev/" + chip).c_str()));
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/dev", ec)) {
        if (!entry.path().filename().string().starts_with("gpiochip")) continue;
        ChipPtr c(gpiod_chip_open(entry.path().c_str()));
        if (!c) continue;
        InfoPtr info(gpiod_chip_get_info(c.get()));
        if (info && chip == gpiod_chip_info_get_label(info.get())) return c;
    }
    errno = ENOENT;
    return nullptr;
}

class GpiodV2Line : public GpioLine {
public:
    GpiodV2Line(RequestPtr request, unsigned offset)
        : request_(std::move(request)), buffer_(gpiod_edge_event_buffer_new(16)), offset_(offset) {}

    Result<bool> level() override {
        const auto v = gpiod_line_request_get_value(request_.get(), offset_);
        if (v == GPIOD_LINE_VALUE_ERROR)
            return make_error(ExitCode::Runtime, "gpio: reading line {}: {}", offset_, std::strerror(errno));
        return v == GPIOD_LINE_VALUE_ACTIVE;
    }

    Result<std::size_t> read_events(std::span<LineEvent> out) override {
        std::size_t n = 0;
        const int fd = gpiod_line_request_get_fd(request_.get());
        while (n < out.size()) {
            pollfd p{fd, POLLIN, 0};
            const int ready = ::poll(&p, 1, 0);  // never wait: the frame loop must not block
            if (ready < 0 && errno == EINTR) continue;
            if (ready <= 0) break;
            if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
                return make_error(ExitCode::Runtime, "gpio: line {} is gone", offset_);
            const int got = gpiod_line_request_read_edge_events(request_.get(), buffer_.get(), 16);
            if (got < 0) {
                if (errno == EAGAIN || errno == EINTR) break;
                return make_error(ExitCode::Runtime, "gpio: line {}: {}", offset_, std::strerror(errno));
            }
            for (int i = 0; i < got && n < out.size(); ++i) {
                gpiod_edge_event* e =
                    gpiod_edge_event_buffer_get_event(buffer_.get(), static_cast<unsigned long>(i));
                out[n++] = LineEvent{gpiod_edge_event_get_event_type(e) == GPIOD_EDGE_EVENT_RISING_EDGE,
                                     static_cast<double>(gpiod_edge_event_get_timestamp_ns(e)) * 1e-9};
            }
            if (got < 16) break;
        }
        return n;
    }

private:
    RequestPtr request_;
    BufferPtr buffer_;
    unsigned offset_;
};

class GpiodV2Backend : public GpioBackend {
public:
    std::string_view name() const override { return "libgpiod 2"; }

    Result<std::unique_ptr<GpioLine>> request(const LineRequest& r) override {
        errno = 0;
        ChipPtr chip = open_chip(r.chip);
        if (!chip) return gpio_request_error(r, errno ? errno : ENOENT);
        int offset = is_number(r.line) ? std::stoi(r.line)
                                       : gpiod_chip_get_line_offset_from_name(chip.get(), r.line.c_str());
        if (offset < 0) return gpio_request_error(r, ENOENT);

        SettingsPtr settings(gpiod_line_settings_new());
        LineConfigPtr line_config(gpiod_line_config_new());
        RequestConfigPtr request_config(gpiod_request_config_new());
        if (!settings || !line_config || !request_config) return gpio_request_error(r, ENOMEM);
        gpiod_line_settings_set_direction(settings.get(), GPIOD_LINE_DIRECTION_INPUT);
        gpiod_line_settings_set_edge_detection(settings.get(), GPIOD_LINE_EDGE_BOTH);
        gpiod_line_settings_set_event_clock(settings.get(), GPIOD_LINE_CLOCK_MONOTONIC);
        gpiod_line_settings_set_active_low(settings.get(), r.active_low);
        switch (r.bias) {
            case params::LineBias::AsIs:
                break;
            case params::LineBias::PullUp:
                gpiod_line_settings_set_bias(settings.get(), GPIOD_LINE_BIAS_PULL_UP);
                break;
            case params::LineBias::PullDown:
                gpiod_line_settings_set_bias(settings.get(), GPIOD_LINE_BIAS_PULL_DOWN);
                break;
            case params::LineBias::Disabled:
                gpiod_line_settings_set_bias(settings.get(), GPIOD_LINE_BIAS_DISABLED);
                break;
        }
        const unsigned offsets[] = {static_cast<unsigned>(offset)};
        if (gpiod_line_config_add_line_settings(line_config.get(), offsets, 1, settings.get()) < 0)
            return gpio_request_error(r, errno);
        gpiod_request_config_set_consumer(request_config.get(), "puddle");
        RequestPtr request(gpiod_chip_request_lines(chip.get(), request_config.get(), line_config.get()));
        if (!request) return gpio_request_error(r, errno);
        std::unique_ptr<GpioLine> out = std::make_unique<GpiodV2Line>(std::move(request), offsets[0]);
        return out;  // the request keeps its own descriptor; the chip handle can close
    }

    std::vector<GpioChipInfo> chips() override {
        std::vector<GpioChipInfo> out;
        for (const std::string& path : gpio_chip_paths()) {
            ChipPtr chip(gpiod_chip_open(path.c_str()));
            InfoPtr info(chip ? gpiod_chip_get_info(chip.get()) : nullptr);
            if (!info) {
                out.push_back({path, "", 0, std::strerror(errno)});
                continue;
            }
            out.push_back({gpiod_chip_info_get_name(info.get()), gpiod_chip_info_get_label(info.get()),
                           static_cast<unsigned>(gpiod_chip_info_get_num_lines(info.get())), ""});
        }
        return out;
    }
};

}  // namespace

std::unique_ptr<GpioBackend> make_gpiod_backend() {
    return std::make_unique<GpiodV2Backend>();
}

}  // namespace puddle::io
