#pragma once
// Starting a worker thread (the background jobs, the pipeline compiler) with every signal blocked, as
// Mesa's threads are: SIGTERM, SIGINT and SIGHUP are for the frame loop's signalfd (app/signals.hpp),
// and one delivered to a worker that does not block it would take its default action and end the
// process. Workers may start before the frame loop blocks those signals on the main thread.

#include <pthread.h>

#include <csignal>
#include <thread>
#include <utility>

namespace puddle {

template <class F>
std::jthread start_worker_thread(F&& body) {
    sigset_t all, previous;  // the new thread inherits this thread's mask, with no gap
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &previous);
    std::jthread thread(std::forward<F>(body));
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return thread;
}

}  // namespace puddle
