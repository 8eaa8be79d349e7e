#pragma once
// Links pipelines' programs on a worker thread (every signal blocked: util/worker_thread.hpp), in a context
// that shares objects with the frame thread's (gpu/worker_context.hpp), so a look or variant chosen while the
// display runs never stops the frame loop or the watchdog ping for a compile (nothing slow on the
// frame thread). The frame thread submits a PipelineDesc and polls the job; Device::take_pipeline turns a
// finished job into a Pipeline. Jobs run one at a time, in submission order.
//
// Synchronisation: the worker calls glFinish after linking, before it marks the job done, so the program
// is complete when the frame thread first uses it (GLES 3.2 section 5.3, "Propagating Changes to
// Objects": a change made in one context is seen by another once it is complete and the object is bound
// again). A job dropped by its requester is skipped, or its program deleted on whichever thread lets go
// of the job last (both have a sharing context current).

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "gpu/handle.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/worker_context.hpp"
#include "util/result.hpp"

namespace puddle::gpu {

struct CompileJob {
    PipelineDesc desc;
    // Written by the worker before done: the program, its compile error, or (worker_unavailable) why the
    // worker's context could not be made current, when the requester should build it itself.
    std::optional<Result<GlHandle<detail::delete_program>>> result;
    bool worker_unavailable = false;
    std::atomic<bool> done{false};
};

class PipelineCompiler {
public:
    // Starts the worker, which makes `context` current before its first job. When that fails, every job
    // is finished at once with worker_unavailable and the error.
    explicit PipelineCompiler(std::unique_ptr<WorkerContext> context);
    PipelineCompiler(const PipelineCompiler&) = delete;
    PipelineCompiler& operator=(const PipelineCompiler&) = delete;
    // Waits for the job being linked (one link: the bound on shutdown), skips the rest, releases the
    // context on the worker and joins it.
    ~PipelineCompiler();

    // Queues desc; poll the job's `done` (acquire) and then read `result`.
    std::shared_ptr<CompileJob> submit(PipelineDesc desc);

private:
    void run(std::stop_token stop);

    std::unique_ptr<WorkerContext> context_;
    std::mutex mutex_;
    std::condition_variable_any wake_;
    std::deque<std::shared_ptr<CompileJob>> queue_;
    std::jthread worker_;  // last: joined before the members it uses die
};

}  // namespace puddle::gpu
