#pragma once
// Slow CPU work (decoding a large image) on one worker thread, off the frame thread, which only submits
// and polls. One job runs at a time and the newest submission wins: submitting asks a running job to
// stop (through its stop_token, checked between its steps), replaces a job still waiting, and only the
// newest job's result is ever handed back. The thread starts with the first submission, so a run that
// never submits has none; destruction asks the running job to stop and waits for it to return.
// The worker blocks every signal, as Mesa's threads do: SIGTERM, SIGINT and SIGHUP are for the frame
// loop's signalfd (app/signals.hpp), and one delivered to a worker that does not block it would take
// its default action and end the process.

#include <pthread.h>

#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <utility>

namespace puddle {

template <class T>
class BackgroundJob {
public:
    using Work = std::function<T(std::stop_token)>;

    BackgroundJob() = default;
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;
    ~BackgroundJob() {
        {
            std::lock_guard lock(mutex_);
            pending_.reset();
            job_stop_.request_stop();
        }
        worker_.request_stop();  // wakes the wait; the jthread member then joins
    }

    // Runs `work` on the worker thread as soon as the job before it (if any) has returned.
    void submit(Work work) {
        std::lock_guard lock(mutex_);
        ++submitted_;
        pending_ = std::move(work);
        result_.reset();
        job_stop_.request_stop();
        if (!worker_.joinable()) {
            sigset_t all, previous;  // the new thread inherits this thread's mask, with no gap
            sigfillset(&all);
            pthread_sigmask(SIG_BLOCK, &all, &previous);
            worker_ = std::jthread([this](std::stop_token stop) { run(stop); });
            pthread_sigmask(SIG_SETMASK, &previous, nullptr);
        }
        waiting_.notify_one();
    }

    // The newest submission's result, once, when it has finished; otherwise nothing.
    std::optional<T> take() {
        std::lock_guard lock(mutex_);
        return std::exchange(result_, std::nullopt);
    }

    // True from a submission until its result has been taken.
    bool busy() const {
        std::lock_guard lock(mutex_);
        return finished_ != submitted_ || result_.has_value();
    }

    // True from a submission until it has returned (its result may then wait to be taken).
    bool running() const {
        std::lock_guard lock(mutex_);
        return finished_ != submitted_;
    }

private:
    void run(std::stop_token thread_stop) {
        std::unique_lock lock(mutex_);
        while (waiting_.wait(lock, thread_stop, [this] { return pending_.has_value(); }) &&
               !thread_stop.stop_requested()) {
            Work work = std::move(*pending_);
            pending_.reset();
            const std::uint64_t number = submitted_;
            job_stop_ = std::stop_source();
            const std::stop_token job_stop = job_stop_.get_token();
            lock.unlock();
            std::optional<T> out(work(job_stop));
            lock.lock();
            if (number == submitted_) {  // a newer submission makes this result stale
                result_ = std::move(out);
                finished_ = number;
            }
        }
    }

    mutable std::mutex mutex_;
    std::condition_variable_any waiting_;
    std::optional<Work> pending_;
    std::optional<T> result_;
    std::stop_source job_stop_;
    std::uint64_t submitted_ = 0;
    std::uint64_t finished_ = 0;  // the submission whose result is (or was) in result_
    std::jthread worker_;         // last: stopped and joined before the members it uses die
};

}  // namespace puddle
