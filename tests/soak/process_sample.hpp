#pragma once
// What the soak watches in its own process: resident memory and open file descriptors.

namespace puddle::soak {

struct ProcessSample {
    long rss_kib = 0;   // VmRSS of /proc/self/status (what /proc/self/statm's second field counts, in KiB)
    long peak_kib = 0;  // VmHWM: the high-water mark since start
    int open_fds = 0;   // entries of /proc/self/fd, not counting the one that lists them
};

ProcessSample sample_process();

}  // namespace puddle::soak
