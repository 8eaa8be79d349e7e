#include "app/signals.hpp"

#include <sys/signalfd.h>
#include <unistd.h>

namespace puddle::app {

namespace {

sigset_t stop_set() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    return set;
}

}  // namespace

void block_stop_signals() {
    const sigset_t set = stop_set();
    sigprocmask(SIG_BLOCK, &set, nullptr);  // one thread yet: the process's mask
}

void release_stop_signals_for_one_shot() {
    std::signal(SIGHUP, SIG_IGN);  // discards a pending SIGHUP too (POSIX): it is no stop
    const sigset_t set = stop_set();
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

StopSignals::StopSignals() {
    const sigset_t set = stop_set();
    pthread_sigmask(SIG_BLOCK, &set, &previous_);
    fd_.reset(signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC));
}

StopSignals::~StopSignals() {
    fd_.reset();
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

bool StopSignals::requested() {
    signalfd_siginfo info{};
    while (!last_ && fd_ && read(fd_.get(), &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
        if (info.ssi_signo == SIGHUP)
            reload_ = true;
        else
            last_ = static_cast<int>(info.ssi_signo);
    }
    return last_ != 0;
}

}  // namespace puddle::app
