// BackgroundJob: work runs off the calling thread, the newest submission wins, a superseded job is asked
// to stop, and destruction stops a running job instead of waiting for it to finish on its own.
#include "util/background_job.hpp"

#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

namespace puddle {
namespace {

using namespace std::chrono_literals;

template <class T>
std::optional<T> wait_for_result(BackgroundJob<T>& job) {
    for (int i = 0; i < 10000; ++i) {
        if (auto r = job.take()) return r;
        std::this_thread::sleep_for(1ms);
    }
    return std::nullopt;
}

// Runs until asked to stop; says whether it was.
int until_stopped(std::stop_token stop, std::atomic<bool>& started, std::atomic<bool>& saw_stop, int value) {
    started = true;
    while (!stop.stop_requested()) std::this_thread::sleep_for(1ms);
    saw_stop = true;
    return value;
}

TEST(BackgroundJob, RunsOffTheCallingThreadAndHandsTheResultOverOnce) {
    BackgroundJob<std::thread::id> job;
    EXPECT_FALSE(job.busy());
    job.submit([](std::stop_token) { return std::this_thread::get_id(); });
    EXPECT_TRUE(job.busy());
    const auto id = wait_for_result(job);
    ASSERT_TRUE(id);
    EXPECT_NE(*id, std::this_thread::get_id());
    EXPECT_FALSE(job.busy());
    EXPECT_FALSE(job.take()) << "a result is handed over once";
}

TEST(BackgroundJob, RunningEndsWhenTheJobReturnsAndBusyWhenItsResultIsTaken) {
    BackgroundJob<int> job;
    EXPECT_FALSE(job.running());
    std::atomic<bool> go{false};
    job.submit([&](std::stop_token) {
        while (!go) std::this_thread::sleep_for(1ms);
        return 7;
    });
    EXPECT_TRUE(job.running());
    go = true;
    for (int i = 0; i < 10000 && job.running(); ++i) std::this_thread::sleep_for(1ms);
    EXPECT_FALSE(job.running());
    EXPECT_TRUE(job.busy()) << "the result waits to be taken";
    EXPECT_EQ(job.take(), 7);
    EXPECT_FALSE(job.busy());
}

TEST(BackgroundJob, TheNewestSubmissionWinsAndTheOlderOneIsAskedToStop) {
    BackgroundJob<int> job;
    std::atomic<bool> started{false}, saw_stop{false};
    job.submit([&](std::stop_token stop) { return until_stopped(stop, started, saw_stop, 1); });
    while (!started) std::this_thread::sleep_for(1ms);
    job.submit([](std::stop_token) { return 2; });
    const auto result = wait_for_result(job);
    ASSERT_TRUE(result);
    EXPECT_EQ(*result, 2) << "the stale job's result is never handed over";
    EXPECT_TRUE(saw_stop);
    std::this_thread::sleep_for(20ms);
    EXPECT_FALSE(job.take());
    EXPECT_FALSE(job.busy());
}

// A SIGTERM delivered to a worker that did not block it would end the process before the frame loop's
// signalfd saw it (the camera worker starts before app::StopSignals blocks the main thread's signals).
TEST(BackgroundJob, TheWorkerBlocksSignalsAndTheCallersMaskIsUnchanged) {
    sigset_t before;
    pthread_sigmask(SIG_SETMASK, nullptr, &before);
    BackgroundJob<sigset_t> job;
    job.submit([](std::stop_token) {
        sigset_t mask;
        pthread_sigmask(SIG_SETMASK, nullptr, &mask);
        return mask;
    });
    const auto mask = wait_for_result(job);
    ASSERT_TRUE(mask);
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) EXPECT_EQ(sigismember(&*mask, sig), 1) << strsignal(sig);
    sigset_t after;
    pthread_sigmask(SIG_SETMASK, nullptr, &after);
    for (int sig : {SIGTERM, SIGINT, SIGHUP}) EXPECT_EQ(sigismember(&after, sig), sigismember(&before, sig));
}

TEST(BackgroundJob, DestructionStopsARunningJob) {
    std::atomic<bool> started{false}, saw_stop{false};
    {
        BackgroundJob<int> job;
        job.submit([&](std::stop_token stop) { return until_stopped(stop, started, saw_stop, 1); });
        while (!started) std::this_thread::sleep_for(1ms);
    }
    EXPECT_TRUE(saw_stop);
}

}  // namespace
}  // namespace puddle
