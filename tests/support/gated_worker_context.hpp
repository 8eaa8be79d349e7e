#pragma once
// A display's worker context made current only once the test opens the gate: until then the pipeline
// compiler's worker cannot link anything, as if every compile took as long as the test wants. Open it
// before the Device dies: the compiler's destructor waits for its worker.

#include <condition_variable>
#include <memory>
#include <mutex>

#include "gpu/worker_context.hpp"

namespace puddle::test {

class GatedContext final : public gpu::WorkerContext {
public:
    explicit GatedContext(std::unique_ptr<gpu::WorkerContext> inner) : inner_(std::move(inner)) {}
    Result<void> make_current() override {
        std::unique_lock lock(mutex_);
        opened_.wait(lock, [this] { return open_; });
        return inner_->make_current();
    }
    void release() override { inner_->release(); }
    void open() {
        {
            std::lock_guard lock(mutex_);
            open_ = true;
        }
        opened_.notify_all();
    }

private:
    std::unique_ptr<gpu::WorkerContext> inner_;
    std::mutex mutex_;
    std::condition_variable opened_;
    bool open_ = false;
};

}  // namespace puddle::test
