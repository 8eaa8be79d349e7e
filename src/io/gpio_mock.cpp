#include "io/gpio_mock.hpp"

#include <fcntl.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "util/safe_quote.hpp"

namespace puddle::io {

namespace {
constexpr int mock_line_count = 64;
constexpr std::size_t queue_size = 64;  // like the kernel's event FIFO: the oldest edges drop when full
constexpr std::size_t max_script_line = 4096;          // a command is a few words
constexpr std::size_t max_script_pending = 64 * 1024;  // read ahead, at most
constexpr double max_wait_seconds = 86400;
constexpr int bad_lines_warned = 3;
}  // namespace

struct MockGpio::Chip {
    std::string name, label;
    bool present = true;
    std::array<int, mock_line_count> raw{};  // -1: undriven (sits at its bias)
    std::array<int, mock_line_count> error{};
    struct Listener;
    std::vector<Listener*> listeners;
    Chip() { raw.fill(-1); }
};

struct MockGpio::Chip::Listener {
    int offset = 0;
    bool active_low = false;
    std::array<LineEvent, queue_size> queue{};
    std::size_t head = 0, count = 0;
};

namespace {

class MockLine : public GpioLine {
public:
    MockLine(std::shared_ptr<MockGpio::Chip> chip, int offset, const LineRequest& r)
        : chip_(std::move(chip)) {
        listener_.offset = offset;
        listener_.active_low = r.active_low;
        pull_up_ = r.bias == params::LineBias::PullUp;
        chip_->listeners.push_back(&listener_);
    }
    ~MockLine() override { std::erase(chip_->listeners, &listener_); }

    Result<bool> level() override {
        if (!chip_->present) return make_error(ExitCode::Runtime, "gpio: {} is gone", chip_->name);
        const int raw = chip_->raw[static_cast<std::size_t>(listener_.offset)];
        const bool high = raw < 0 ? pull_up_ : raw == 1;
        return high != listener_.active_low;
    }

    Result<std::size_t> read_events(std::span<LineEvent> out) override {
        if (!chip_->present) return make_error(ExitCode::Runtime, "gpio: {} is gone", chip_->name);
        std::size_t n = 0;
        while (n < out.size() && listener_.count > 0) {
            out[n++] = listener_.queue[listener_.head];
            listener_.head = (listener_.head + 1) % queue_size;
            --listener_.count;
        }
        return n;
    }

private:
    std::shared_ptr<MockGpio::Chip> chip_;
    MockGpio::Chip::Listener listener_;
    bool pull_up_ = false;
};

}  // namespace

MockGpio::MockGpio(std::string script) : script_(std::move(script)) {
    add_chip("gpiochip0", "mock-gpio");
    if (!script_.empty()) {
        // O_NONBLOCK: opening a FIFO with no writer yet must not wait, and reads never block.
        fd_.reset(::open(script_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
        if (!fd_)
            spdlog::warn("gpio: mock script {} cannot be opened: {}; knobs will not move", script_,
                         std::strerror(errno));
        else
            spdlog::info("gpio: mock backend reading line changes from {}", script_);
    }
}

MockGpio::~MockGpio() = default;

std::vector<GpioChipInfo> MockGpio::chips() {
    std::vector<GpioChipInfo> out;
    for (const auto& [name, chip] : chips_) out.push_back({name, chip->label, mock_line_count, ""});
    return out;
}

void MockGpio::add_chip(const std::string& name, const std::string& label) {
    auto& chip = chips_[name];
    if (!chip) chip = std::make_shared<Chip>();
    chip->name = name;
    chip->label = label.empty() ? name : label;
    chip->present = true;
}

void MockGpio::remove_chip(const std::string& name) {
    if (auto it = chips_.find(name); it != chips_.end()) {
        it->second->present = false;
        // A replugged chip is a new device: its lines start over and old requests stay dead.
        chips_.erase(it);
    }
}

void MockGpio::set_level(const std::string& name, int offset, bool raw_level, double time) {
    auto it = chips_.find(name);
    if (it == chips_.end() || offset < 0 || offset >= mock_line_count) return;
    Chip& chip = *it->second;
    int& raw = chip.raw[static_cast<std::size_t>(offset)];
    const bool changed = raw != static_cast<int>(raw_level);
    raw = raw_level;
    if (!changed) return;
    // Edges read in one poll share `now`; like the kernel's nanosecond stamps, keep them in order.
    time = std::max(time, last_time_ + 1e-6);
    last_time_ = time;
    for (Chip::Listener* l : chip.listeners) {
        if (l->offset != offset) continue;
        const std::size_t at = (l->head + l->count) % queue_size;
        l->queue[at] = LineEvent{raw_level != l->active_low, time};
        if (l->count < queue_size)
            ++l->count;
        else
            l->head = (l->head + 1) % queue_size;
    }
}

void MockGpio::set_error(const std::string& name, int offset, int err) {
    auto it = chips_.find(name);
    if (it == chips_.end() || offset < 0 || offset >= mock_line_count) return;
    it->second->error[static_cast<std::size_t>(offset)] = err;
}

Result<std::unique_ptr<GpioLine>> MockGpio::request(const LineRequest& r) {
    std::string name = r.chip;
    if (name.starts_with("/dev/")) name = name.substr(5);
    if (is_number(name)) name = "gpiochip" + name;
    std::shared_ptr<Chip> chip;
    for (auto& [key, c] : chips_)
        if (key == name || c->label == r.chip) chip = c;
    if (!chip) return gpio_request_error(r, ENOENT);
    int offset = -1;
    if (is_number(r.line))
        offset = std::stoi(r.line);
    else if (r.line.starts_with("GPIO") && is_number(r.line.substr(4)))
        offset = std::stoi(r.line.substr(4));
    if (offset < 0 || offset >= mock_line_count) return gpio_request_error(r, ENOENT);
    if (const int err = chip->error[static_cast<std::size_t>(offset)]) return gpio_request_error(r, err);
    for (const Chip::Listener* l : chip->listeners)
        if (l->offset == offset) return gpio_request_error(r, EBUSY);
    std::unique_ptr<GpioLine> line = std::make_unique<MockLine>(chip, offset, r);
    return line;
}

bool MockGpio::command(std::string_view text, double now) {
    std::istringstream in{std::string(text)};
    std::string a, b, c;
    in >> a >> b >> c;
    if (a.empty() || a[0] == '#') return false;
    if (a == "remove" && !b.empty()) return remove_chip(b), true;
    if (a == "add" && !b.empty()) return add_chip(b, c), true;
    if ((a == "busy" || a == "deny") && is_number(c))
        return set_error(b, std::stoi(c), a == "busy" ? EBUSY : EACCES), true;
    if (is_number(b) && (c == "0" || c == "1")) return set_level(a, std::stoi(b), c == "1", now), true;
    return false;
}

void MockGpio::note_bad_line(std::string_view line, std::string_view why) {
    const auto level = ++bad_lines_ <= bad_lines_warned ? spdlog::level::warn : spdlog::level::debug;
    spdlog::log(level, "gpio: mock script {}: {}: '{}'{}", script_, why, safe_quote(line, 120),
                bad_lines_ == bad_lines_warned ? " (further bad lines are logged at debug level)" : "");
}

void MockGpio::poll(double now) {
    if (!fd_) return;
    char buffer[1024];
    // A huge script is read over several frames, never all at once into memory, and no frame reads more
    // than max_script_pending bytes: a source that never runs dry (/dev/zero) skipping one endless line
    // would otherwise hold the frame in read() for ever.
    for (std::size_t read_now = 0; pending_.size() < max_script_pending && read_now < max_script_pending;) {
        const ssize_t n = ::read(fd_.get(), buffer, sizeof buffer);
        if (n <= 0) break;
        read_now += static_cast<std::size_t>(n);
        std::string_view chunk(buffer, static_cast<std::size_t>(n));
        if (skipping_long_line_) {  // the rest of a line that was too long to be a command
            const auto nl = chunk.find('\n');
            if (nl == std::string_view::npos) continue;
            chunk.remove_prefix(nl + 1);
            skipping_long_line_ = false;
        }
        pending_.append(chunk);
    }
    if (now < resume_at_) return;
    std::size_t start = 0;
    for (std::size_t nl; (nl = pending_.find('\n', start)) != std::string::npos;) {
        const std::string_view line(pending_.data() + start, nl - start);
        start = nl + 1;
        double seconds = 0;
        if (std::sscanf(std::string(line).c_str(), "wait %lf", &seconds) == 1) {
            if (std::isfinite(seconds) && seconds >= 0 && seconds <= max_wait_seconds) {
                resume_at_ = now + seconds;  // the rest of the script runs after that
                break;
            }
            note_bad_line(line, fmt::format("a wait takes 0 to {:g} seconds", max_wait_seconds));
            continue;
        }
        if (!command(line, now) && !line.empty() && line[0] != '#') note_bad_line(line, "not a command");
    }
    pending_.erase(0, start);
    if (pending_.size() > max_script_line && pending_.find('\n') == std::string::npos) {
        spdlog::warn("gpio: mock script {}: a line longer than {} bytes is not a command; skipped it",
                     script_, max_script_line);
        pending_.clear();
        skipping_long_line_ = true;
    }
}

}  // namespace puddle::io
