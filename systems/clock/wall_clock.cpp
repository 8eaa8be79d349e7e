#include "systems/clock/wall_clock.hpp"

#include <fmt/format.h>
#include <sys/timex.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

namespace puddle::systems {

namespace {

// Floor division: whole periods at or before `ns`, for times before the epoch too.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

}  // namespace

std::int64_t system_wall_ns() {
    timespec ts{};
    clock_gettime(CLOCK_REALTIME, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * ns_per_second + ts.tv_nsec;
}

std::int64_t step_at(std::int64_t ns, double steps_per_second) {
    const std::int64_t seconds = floor_div(ns, ns_per_second);
    const std::int64_t rest = ns - seconds * ns_per_second;  // 0 .. 1e9 - 1
    const double whole = static_cast<double>(seconds) * steps_per_second;
    const double base = std::floor(whole);
    // The fraction of `whole` added to the rest's steps before flooring: both are below a few hundred.
    const double part = (whole - base) + static_cast<double>(rest) * 1e-9 * steps_per_second;
    return static_cast<std::int64_t>(base) + static_cast<std::int64_t>(std::floor(part));
}

std::int64_t change_boundary(std::int64_t ns, double period_seconds) {
    const auto period = std::max<std::int64_t>(1, std::llround(period_seconds * 1e9));
    return (floor_div(ns, period) + 2) * period;
}

ClockSync read_clock_sync() {
    timex tx{};  // modes 0: read only
    const int state = adjtimex(&tx);
    ClockSync s;
    if (state == -1) {
        s.problem = fmt::format("adjtimex: {}", std::strerror(errno));
        return s;
    }
    s.synchronised = state != TIME_ERROR && !(tx.status & STA_UNSYNC);
    s.estimated_error_us = tx.esterror;
    s.maximum_error_us = tx.maxerror;
    return s;
}

std::string describe(const ClockSync& s) {
    if (!s.problem.empty()) return "unknown (" + s.problem + ")";
    if (!s.synchronised)
        return fmt::format(
            "NOT synchronised (the kernel's STA_UNSYNC: no NTP or PTP daemon disciplines it; maximum error "
            "{:.1f} ms)",
            static_cast<double>(s.maximum_error_us) / 1000.0);
    return fmt::format("synchronised, estimated error {:.3f} ms (maximum {:.1f} ms)",
                       static_cast<double>(s.estimated_error_us) / 1000.0,
                       static_cast<double>(s.maximum_error_us) / 1000.0);
}

double warmup_residual(double damping, std::int64_t steps) {
    return std::pow(damping, 0.5 * static_cast<double>(steps));
}

}  // namespace puddle::systems
