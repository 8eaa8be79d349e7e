#pragma once
// Sets the TZ environment variable (and tzset()) for one test, restoring the previous zone after; and
// local_instant, a local clock time in that zone as a UTC instant.
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

namespace puddle::test {

class TzGuard {
public:
    explicit TzGuard(const char* zone) {
        if (const char* old = std::getenv("TZ")) old_ = old;
        ::setenv("TZ", zone, 1);
        ::tzset();
    }
    ~TzGuard() {
        if (old_)
            ::setenv("TZ", old_->c_str(), 1);
        else
            ::unsetenv("TZ");
        ::tzset();
    }
    TzGuard(const TzGuard&) = delete;
    TzGuard& operator=(const TzGuard&) = delete;

private:
    std::optional<std::string> old_;
};

// A local clock time as a UTC instant (seconds since the Unix epoch), by mktime: the zone's rules,
// daylight saving included; a time that happens twice is taken as mktime takes it (tm_isdst = -1).
inline double local_instant(int year, int month, int day, int hour, int minute) {
    tm l{};
    l.tm_year = year - 1900;
    l.tm_mon = month - 1;
    l.tm_mday = day;
    l.tm_hour = hour;
    l.tm_min = minute;
    l.tm_isdst = -1;
    return static_cast<double>(mktime(&l));
}

}  // namespace puddle::test
