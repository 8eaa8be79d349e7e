#include "app/process_setup.hpp"

#include <malloc.h>

#include <csignal>

namespace puddle::app {

void setup_process() {
    std::signal(SIGPIPE, SIG_IGN);
    mallopt(M_ARENA_MAX, 1);
}

}  // namespace puddle::app
