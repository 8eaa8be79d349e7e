// The pipeline compiler (gpu/pipeline_compiler.hpp) on its own: jobs are linked one at a time in the order
// they were submitted, each with its own result, and a worker whose context cannot be made current finishes
// every job at once saying so. Device::request_pipeline on top of it: device_test.cpp.
#include "gpu/pipeline_compiler.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class PipelineCompilerTest : public test::DeviceFixture {};

// Waits at most 30 s for a job; false if it is still not done.
bool wait_done(const CompileJob& job) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!job.done.load(std::memory_order_acquire)) {
        if (std::chrono::steady_clock::now() > give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

const PipelineDesc broken{.label = "broken wave",
                          .fragment = "wave_step.frag",
                          .defines = {"MAX_DROPS -1"},
                          .textures = {"u_field"},
                          .uniform_blocks = {"Drops"}};

// Fails if jobs ran out of order or in parallel: when the last is done, every earlier one must be.
TEST_F(PipelineCompilerTest, JobsFinishInSubmissionOrderEachWithItsOwnResult) {
    auto context = display_->create_worker_context();
    ASSERT_TRUE(context.ok()) << context.error().message;
    PipelineCompiler compiler(std::move(context).value());
    const std::vector<std::shared_ptr<CompileJob>> jobs{
        compiler.submit({.label = "street", .fragment = "street.frag"}), compiler.submit(broken),
        compiler.submit({.label = "floor", .fragment = "floor.frag"})};
    ASSERT_TRUE(wait_done(*jobs.back())) << "still linking after 30 s";
    for (const auto& job : jobs) {
        SCOPED_TRACE(job->desc.label);
        ASSERT_TRUE(job->done.load(std::memory_order_acquire)) << "an earlier job was not finished first";
        ASSERT_TRUE(job->result.has_value());
        EXPECT_FALSE(job->worker_unavailable);
    }
    EXPECT_TRUE(*jobs[0]->result) << jobs[0]->result->error().message;
    ASSERT_FALSE(*jobs[1]->result);
    EXPECT_NE(jobs[1]->result->error().message.find("gpu: pipeline 'broken wave': wave_step.frag:"),
              std::string::npos)
        << jobs[1]->result->error().message;
    EXPECT_TRUE(*jobs[2]->result) << jobs[2]->result->error().message;
    EXPECT_NE(jobs[0]->result->value().get(), jobs[2]->result->value().get()) << "two programs";
}

// A worker context that cannot be made current (a driver without shared surfaceless contexts).
struct BrokenWorkerContext final : WorkerContext {
    Result<void> make_current() override {
        return make_error(ExitCode::Display, "egl: eglMakeCurrent(worker context): EGL_BAD_MATCH");
    }
    void release() override {}
};

TEST_F(PipelineCompilerTest, AWorkerWithoutAContextFinishesEveryJobSayingWhy) {
    PipelineCompiler compiler(std::make_unique<BrokenWorkerContext>());
    for (int i = 0; i < 2; ++i) {
        const auto job = compiler.submit({.label = "street", .fragment = "street.frag"});
        ASSERT_TRUE(wait_done(*job));
        EXPECT_TRUE(job->worker_unavailable);
        ASSERT_TRUE(job->result.has_value());
        ASSERT_FALSE(*job->result);
        EXPECT_EQ(job->result->error().message, "egl: eglMakeCurrent(worker context): EGL_BAD_MATCH");
        EXPECT_EQ(job->desc.label, "street") << "the desc comes back for the requester to build";
    }
}

}  // namespace
}  // namespace puddle::gpu
