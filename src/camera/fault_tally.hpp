#pragma once
// A count of one kind of camera fault (corrupt frames dropped, capture errors retried), reported at
// most once a minute: a camera that sends bad frames 30 times a second must not fill the journal, and
// one that does it once a day must still be heard. The tally only makes the line; the caller logs it.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace puddle::camera {

inline constexpr double fault_report_interval_s = 60.0;

class FaultTally {
public:
    // `device` names the camera; `one` and `many` are what is counted, as the line says it for one
    // fault and for several ("corrupt MJPEG frame dropped", "corrupt MJPEG frames dropped").
    FaultTally(std::string device, std::string one, std::string many)
        : device_(std::move(device)), one_(std::move(one)), many_(std::move(many)) {}

    // Counts `n` faults at `now` (seconds on any steady clock; the camera uses the frame loop's) for
    // `reason`. Returns the line to log when one is due: at once for the first fault, then at most
    // once per fault_report_interval_s, e.g. "camera: /dev/video0: 12 corrupt MJPEG frames dropped in
    // the last minute (premature end of data)". The reason is the last one counted.
    std::optional<std::string> record(double now, std::uint64_t n, std::string_view reason);
    // The line for faults counted since the last line, once the interval is over; nothing otherwise.
    // Cheap enough to call every frame.
    std::optional<std::string> due(double now);
    // Every fault counted since this tally was made.
    std::uint64_t total() const { return total_; }

private:
    std::string device_, one_, many_;
    std::string reason_;
    std::uint64_t total_ = 0;
    std::uint64_t unreported_ = 0;
    double next_line_ = -std::numeric_limits<double>::infinity();
};

}  // namespace puddle::camera
