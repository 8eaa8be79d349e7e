#include "app/process_setup.hpp"

#include <malloc.h>

#include <csignal>

namespace puddle::app {

void setup_process() {
    std::signal(SIGPIPE, SIG_IGN);
    mallopt(M_ARENA_MAX, 1);
    // Fixed thresholds: glibc otherwise raises both after a large block is freed (up to 32 MiB), and then
    // keeps freed memory instead of returning it, so resident memory creeps after a sky or camera load.
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
    mallopt(M_TRIM_THRESHOLD, 512 * 1024);
}

}  // namespace puddle::app
