#pragma once
// Seconds on CLOCK_MONOTONIC as a double (a double keeps seconds since boot to well under a microsecond
// for decades): the clock of the kernel's GPIO event timestamps and of systemd's watchdog, so the knobs
// (live tuning) and the service plugin both read it.

#include <time.h>

namespace puddle {

inline double monotonic_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

}  // namespace puddle
