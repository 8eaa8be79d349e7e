// start_worker_thread (util/worker_thread.hpp): the worker runs with every blockable signal blocked, so a
// SIGTERM meant for the frame loop's signalfd never ends the process through a worker; the starting
// thread's own mask is the same afterwards; the body is the jthread's, stop token included.
#include "util/worker_thread.hpp"

#include <gtest/gtest.h>
#include <pthread.h>

#include <algorithm>
#include <csignal>
#include <stop_token>
#include <thread>
#include <vector>

namespace puddle {
namespace {

sigset_t current_mask() {
    sigset_t mask;
    pthread_sigmask(SIG_BLOCK, nullptr, &mask);
    return mask;
}

// The standard signals (1..31) blocked in `mask`. SIGKILL and SIGSTOP cannot be blocked at all.
std::vector<int> blocked_standard_signals(const sigset_t& mask) {
    std::vector<int> blocked;
    for (int s = 1; s < 32; ++s)
        if (sigismember(&mask, s) == 1) blocked.push_back(s);
    return blocked;
}

std::vector<int> blockable_standard_signals() {
    std::vector<int> all;
    for (int s = 1; s < 32; ++s)
        if (s != SIGKILL && s != SIGSTOP) all.push_back(s);
    return all;
}

// Runs `test` on a thread of its own whose mask starts as `initial`, so the test thread's mask is known.
template <class Test>
void with_mask(const sigset_t& initial, Test test) {
    std::jthread([&] {
        pthread_sigmask(SIG_SETMASK, &initial, nullptr);
        test();
    }).join();
}

TEST(WorkerThread, TheWorkerBlocksEverySignal) {
    sigset_t none;
    sigemptyset(&none);
    std::vector<int> in_worker;
    with_mask(none, [&] {
        start_worker_thread([&] { in_worker = blocked_standard_signals(current_mask()); }).join();
    });
    EXPECT_EQ(in_worker, blockable_standard_signals());
    for (int s : {SIGTERM, SIGINT, SIGHUP})
        EXPECT_EQ(std::count(in_worker.begin(), in_worker.end(), s), 1) << s;
}

TEST(WorkerThread, TheStartingThreadKeepsItsOwnMask) {
    sigset_t only_usr2;
    sigemptyset(&only_usr2);
    sigaddset(&only_usr2, SIGUSR2);
    std::vector<int> after;
    with_mask(only_usr2, [&] {
        start_worker_thread([] {}).join();
        after = blocked_standard_signals(current_mask());
    });
    EXPECT_EQ(after, std::vector<int>{SIGUSR2});
}

// The body may take the jthread's stop token: destroying the thread asks it to stop and joins it.
TEST(WorkerThread, DestroyingTheThreadStopsABodyThatTakesTheStopToken) {
    bool saw_stop = false;
    {
        const std::jthread worker = start_worker_thread([&](std::stop_token stop) {
            while (!stop.stop_requested()) std::this_thread::yield();
            saw_stop = true;
        });
    }
    EXPECT_TRUE(saw_stop);
}

}  // namespace
}  // namespace puddle
