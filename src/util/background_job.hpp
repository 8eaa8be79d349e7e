#pragma once
// Slow CPU work (decoding a large image) on one worker thread, off the frame thread, which only submits
// and polls. One job runs at a time and the newest submission wins: submitting asks a running job to
// stop (through its stop_token, checked between its steps), replaces a job still waiting, and only the
// newest job's result is ever handed back. The thread starts with the first submission, so a run that
// never submits has none; destruction asks the running job to stop and waits for it to return.
// The worker blocks every signal (util/worker_thread.hpp).

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <utility>

#include "util/worker_thread.hpp"

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
        if (!worker_.joinable()) worker_ = start_worker_thread([this](std::stop_token stop) { run(stop); });
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
