#include "camera/fault_tally.hpp"

#include <fmt/format.h>

namespace puddle::camera {

std::optional<std::string> FaultTally::record(double now, std::uint64_t n, std::string_view reason) {
    if (n == 0) return due(now);
    total_ += n;
    unreported_ += n;
    reason_.assign(reason);
    return due(now);
}

std::optional<std::string> FaultTally::due(double now) {
    if (unreported_ == 0 || now < next_line_) return std::nullopt;
    std::string line = fmt::format("camera: {}: {} {} in the last minute ({})", device_, unreported_,
                                   unreported_ == 1 ? one_ : many_, reason_);
    unreported_ = 0;
    next_line_ = now + fault_report_interval_s;
    return line;
}

}  // namespace puddle::camera
