#pragma once
// The wall clock: the system's real-time clock (CLOCK_REALTIME, UTC) behind a resource that tests replace,
// and the arithmetic that turns its time into wave steps for walls of screens kept in step by it
// (wall.clock = "realtime"). Times are integer nanoseconds since the Unix epoch: a double holds
// 1.7e9 s only to 0.24 us, and step boundaries must fall at the same instant on every screen.

#include <cstdint>
#include <functional>
#include <string>

namespace puddle::systems {

inline constexpr std::int64_t ns_per_second = 1'000'000'000;

// Nanoseconds since the Unix epoch (1970-01-01 00:00:00 UTC), from CLOCK_REALTIME.
std::int64_t system_wall_ns();
// The same in seconds (the schedule's calendar times).
inline double system_wall_seconds() {
    return static_cast<double>(system_wall_ns()) * 1e-9;
}

// What the kernel says of the clock's discipline (adjtimex(2); ntp_adjtime in chrony's and linuxptp's
// terms): `synchronised` is false while STA_UNSYNC is set or adjtimex returns TIME_ERROR, which is the case
// until an NTP or PTP daemon has set it; the errors are the kernel's estimate and bound, in microseconds.
struct ClockSync {
    bool synchronised = false;
    long estimated_error_us = 0;  // timex.esterror
    long maximum_error_us = 0;    // timex.maxerror (grows 500 ppm of elapsed time while undisciplined)
    std::string problem;          // adjtimex failed: "adjtimex: why"; empty otherwise
};
ClockSync read_clock_sync();
// "synchronised, estimated error 0.120 ms (maximum 8.4 ms)" or "NOT synchronised (...)".
std::string describe(const ClockSync& sync);

// Resource: the wall clock the schedule and the realtime frame clock read, and the kernel's view of its
// synchronisation. Tests replace them.
struct WallClock {
    std::function<std::int64_t()> now_ns = system_wall_ns;
    std::function<ClockSync()> sync = read_clock_sync;
    double seconds() const { return static_cast<double>(now_ns()) * 1e-9; }
};

// The wave step whose interval holds wall time `ns`: floor(ns * steps_per_second / 1e9), with whole seconds
// and their remainder multiplied apart so the result is the same on every machine (IEEE doubles) and
// exact to 1e-5 of a step at today's times. Step n begins at n / steps_per_second seconds.
std::int64_t step_at(std::int64_t ns, double steps_per_second);

// Where synced changes land (wall.change_period): the next whole multiple of `period_seconds` after `ns`,
// plus one more period, so a change read up to one period late on another screen still meets the same
// boundary. Example: at 12:00:00.3 with a period of 1 s, 12:00:02.0.
std::int64_t change_boundary(std::int64_t ns, double period_seconds);

// The warm-up's length in steps for a field that keeps `damping` of its energy per step, and the share
// of the field's start that it leaves: every mode of the damped wave equation decays as
// damping^(n/2) per n steps (wave_step.frag: next = damping (L+R+D+U)/2 - damping prev, whose
// characteristic roots have modulus sqrt(damping)), so after n steps a difference in the start is
// damping^(n/2) of what it was. With damping = 1 nothing is forgotten: the residual is 1.
double warmup_residual(double damping, std::int64_t steps);

}  // namespace puddle::systems
