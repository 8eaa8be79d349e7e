#pragma once
// A fault that recurs (a connection taken over every few seconds) said once in full and then summarised:
// how many more times, at most once per interval, the interval doubling from first_summary_s to
// max_summary_s. A fault that never ends costs a few lines a day in the journal, not one every few
// seconds, and the first line (with the cause and the fix) stays easy to find.

#include <algorithm>
#include <cstdint>

namespace puddle {

class RecurringFault {
public:
    static constexpr double first_summary_s = 60.0;
    static constexpr double max_summary_s = 3600.0;

    enum class Say { Full, Summary, Nothing };
    struct Report {
        Say say = Say::Nothing;
        std::uint64_t since_said = 0;  // occurrences since the last line said about it, this one included
        std::uint64_t total = 0;       // since it began
        double said_wall = 0;          // when that last line was said (seconds since the Unix epoch)
    };

    // One occurrence at `now` (monotonic seconds) and `wall` (seconds since the Unix epoch, for the
    // summary's "since"): what to log.
    Report occurred(double now, double wall) {
        ++total_;
        ++since_said_;
        last_wall_ = wall;
        Report r{Say::Nothing, since_said_, total_, said_wall_};
        if (total_ == 1) {
            r.say = Say::Full;
            interval_ = first_summary_s;
        } else if (now - said_at_ >= interval_) {
            r.say = Say::Summary;
            interval_ = std::min(interval_ * 2, max_summary_s);
        } else {
            return r;
        }
        said_at_ = now;
        said_wall_ = wall;
        since_said_ = 0;
        return r;
    }
    bool active() const { return total_ > 0; }
    // When it last occurred (seconds since the Unix epoch).
    double last_wall() const { return last_wall_; }
    // The fault ended: the count it reached (0: it was not active); the next occurrence is said in full.
    std::uint64_t clear() {
        const std::uint64_t total = total_;
        *this = {};
        return total;
    }

private:
    std::uint64_t total_ = 0, since_said_ = 0;
    double said_at_ = 0, said_wall_ = 0, last_wall_ = 0, interval_ = first_summary_s;
};

}  // namespace puddle
