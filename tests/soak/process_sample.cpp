#include "soak/process_sample.hpp"

#include <dirent.h>

#include <cstring>

#include "systems/common/frame_stats.hpp"

namespace puddle::soak {

namespace {

int count_open_fds() {
    DIR* dir = opendir("/proc/self/fd");
    if (!dir) return -1;
    int n = 0;
    while (const dirent* e = readdir(dir))
        if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) ++n;
    closedir(dir);
    return n - 1;  // the listing's own descriptor
}

}  // namespace

ProcessSample sample_process() {
    const systems::MemoryStatus m = systems::read_memory_status();
    return {.rss_kib = m.rss_kib, .peak_kib = m.peak_kib, .open_fds = count_open_fds()};
}

}  // namespace puddle::soak
