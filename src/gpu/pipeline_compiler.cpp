#include "gpu/pipeline_compiler.hpp"

#include "gpu/gl.hpp"
#include "gpu/program_link.hpp"
#include "util/worker_thread.hpp"

namespace puddle::gpu {

PipelineCompiler::PipelineCompiler(std::unique_ptr<WorkerContext> context) : context_(std::move(context)) {
    worker_ = start_worker_thread([this](std::stop_token stop) { run(stop); });
}

PipelineCompiler::~PipelineCompiler() {
    worker_.request_stop();
    if (worker_.joinable()) worker_.join();
}

std::shared_ptr<CompileJob> PipelineCompiler::submit(PipelineDesc desc) {
    auto job = std::make_shared<CompileJob>();
    job->desc = std::move(desc);
    {
        std::lock_guard lock(mutex_);
        queue_.push_back(job);
    }
    wake_.notify_one();
    return job;
}

void PipelineCompiler::run(std::stop_token stop) {
    std::optional<Result<void>> current;  // made current before the first job, not at start-up
    for (;;) {
        std::shared_ptr<CompileJob> job;
        {
            std::unique_lock lock(mutex_);
            if (!wake_.wait(lock, stop, [this] { return !queue_.empty(); })) break;
            job = std::move(queue_.front());
            queue_.pop_front();
        }
        if (job.use_count() == 1) continue;  // its requester let go of it before it started
        if (!current) current = context_->make_current();
        if (!*current) {
            job->result = current->error();
            job->worker_unavailable = true;
        } else {
            job->result = link_program(job->desc);
            glFinish();  // complete before the frame thread binds it (see the header)
        }
        job->done.store(true, std::memory_order_release);
        // `job` dies here, or later on the frame thread: either way with a sharing context current.
    }
    {
        std::lock_guard lock(mutex_);
        queue_.clear();
    }
    if (current && *current) context_->release();
}

}  // namespace puddle::gpu
