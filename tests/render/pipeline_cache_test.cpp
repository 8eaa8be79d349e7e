// A pass's pipelines keyed by variant (render/pipeline_cache.hpp): a key is built once and reused, a
// failed build is logged once and never tried again, and while a new key builds off the frame thread the
// pipeline returned last stands in (none before anything was ever ready).
#include "render/pipeline_cache.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "support/gated_worker_context.hpp"
#include "support/gpu_fixture.hpp"
#include "support/log_lines.hpp"

namespace puddle::test {
namespace {

using render::BuiltPipeline;

// Three variants of a small pass: two that build, one that cannot (a define that breaks the shader).
enum class Variant { turn, scale, broken };
using Cache = render::PipelineCache<Variant, 3, render::enum_index<Variant>>;

gpu::PipelineDesc desc_of(Variant v) {
    switch (v) {
        case Variant::turn:
            return {.label = "turn", .fragment = "output_canvas.frag", .textures = {"u_canvas"}};
        case Variant::scale:
            return {.label = "scale",
                    .fragment = "output_canvas.frag",
                    .defines = {"SCALED"},
                    .textures = {"u_canvas"}};
        case Variant::broken:
            break;
    }
    return {.label = "broken wave",
            .fragment = "wave_step.frag",
            .defines = {"MAX_DROPS -1"},
            .textures = {"u_field"},
            .uniform_blocks = {"Drops"}};
}

// make_desc for a variant, counting how often the cache asked for a build.
struct Builds {
    int count = 0;
    auto of(Variant v) {
        return [this, v] {
            ++count;
            return desc_of(v);
        };
    }
};

// The error lines logged while it lives.
struct ErrorLines : test::LogLines {
    ErrorLines() : LogLines(spdlog::level::err) {}
};

class PipelineCacheTest : public DeviceFixture {
protected:
    // Starts background compiles behind a gate the test opens; returns the gate.
    GatedContext& gate_compiles() {
        auto context = display_->create_worker_context();
        EXPECT_TRUE(context.ok()) << context.error().message;
        auto gated = std::make_unique<GatedContext>(std::move(context).value());
        GatedContext& gate = *gated;
        device_->start_background_compiles(std::move(gated));
        return gate;
    }

    // Calls request_or_last the way the frame loop does until `v` is built or 30 s have passed; what the
    // last call returned.
    const BuiltPipeline* poll_until_built(Cache& cache, Variant v, Builds& builds) {
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        const BuiltPipeline* got = nullptr;
        while (std::chrono::steady_clock::now() < give_up) {
            got = cache.request_or_last(*device_, v, builds.of(v));
            if (cache.find(v)) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        return got;
    }
};

// Opens the gate when the test ends, however it ends: the compiler's worker must finish before the Device
// dies.
struct OpenOnExit {
    GatedContext& gate;
    ~OpenOnExit() { gate.open(); }
};

TEST_F(PipelineCacheTest, AKeyIsBuiltOnceAndReused) {
    Cache cache;
    Builds builds;
    ASSERT_TRUE(cache.ensure(*device_, Variant::turn, builds.of(Variant::turn)).ok());
    const BuiltPipeline* first = cache.find(Variant::turn);
    ASSERT_NE(first, nullptr);
    const auto name = first->pipeline.id();
    EXPECT_NE(name, 0u);
    for (int frame = 0; frame < 5; ++frame) {
        const BuiltPipeline* again = cache.request(*device_, Variant::turn, builds.of(Variant::turn));
        ASSERT_EQ(again, first);
        EXPECT_EQ(again->pipeline.id(), name) << "the same GL program, not a new one";
    }
    EXPECT_TRUE(cache.ensure(*device_, Variant::turn, builds.of(Variant::turn)).ok());
    EXPECT_EQ(builds.count, 1);
    EXPECT_EQ(cache.find(Variant::scale), nullptr) << "a key nobody asked for is not built";
}

TEST_F(PipelineCacheTest, AFailedBuildIsLoggedOnceAndNotRetried) {
    GatedContext& gate = gate_compiles();
    gate.open();  // a real worker: the failure comes back from the compiler's thread
    const ErrorLines errors;
    Cache cache;
    Builds builds;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!cache.failed(Variant::broken) && std::chrono::steady_clock::now() < give_up) {
        EXPECT_EQ(cache.request(*device_, Variant::broken, builds.of(Variant::broken)), nullptr);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_TRUE(cache.failed(Variant::broken)) << "still building after 30 s";
    for (int frame = 0; frame < 60; ++frame)
        EXPECT_EQ(cache.request(*device_, Variant::broken, builds.of(Variant::broken)), nullptr);
    auto at_start_up = cache.ensure(*device_, Variant::broken, builds.of(Variant::broken));
    ASSERT_FALSE(at_start_up.ok());
    EXPECT_EQ(at_start_up.error().message, "gpu: pipeline failed to build before");
    EXPECT_EQ(builds.count, 1) << "a failed key is never built again";
    EXPECT_EQ(errors.count("wave_step.frag:"), 1) << "one line naming the shader, not one a frame";
}

TEST_F(PipelineCacheTest, NothingIsReturnedBeforeAnythingWasReady) {
    GatedContext& gate = gate_compiles();
    const OpenOnExit open_at_end{gate};
    Cache cache;
    Builds builds;
    for (int frame = 0; frame < 3; ++frame) {
        EXPECT_EQ(cache.request_or_last(*device_, Variant::turn, builds.of(Variant::turn)), nullptr);
        EXPECT_EQ(cache.request(*device_, Variant::turn, builds.of(Variant::turn)), nullptr);
    }
    EXPECT_EQ(builds.count, 1) << "one build in flight, asked for once";
    gate.open();
    const BuiltPipeline* built = poll_until_built(cache, Variant::turn, builds);
    ASSERT_NE(built, nullptr) << "still building after 30 s";
    EXPECT_EQ(built, cache.find(Variant::turn));
}

TEST_F(PipelineCacheTest, TheVariantReturnedLastStandsInWhileAnotherBuildsAndAfterOneFails) {
    GatedContext& gate = gate_compiles();
    const OpenOnExit open_at_end{gate};
    const ErrorLines errors;
    Cache cache;
    Builds builds;
    // At start-up: built at once on this thread, whatever the worker does.
    ASSERT_TRUE(cache.ensure(*device_, Variant::turn, builds.of(Variant::turn)).ok());
    const BuiltPipeline* turn = cache.request_or_last(*device_, Variant::turn, builds.of(Variant::turn));
    ASSERT_NE(turn, nullptr);
    ASSERT_EQ(turn, cache.find(Variant::turn));

    // The worker is held: `scale` is building, and `turn` stands in for it.
    for (int frame = 0; frame < 3; ++frame)
        EXPECT_EQ(cache.request_or_last(*device_, Variant::scale, builds.of(Variant::scale)), turn);
    EXPECT_EQ(cache.find(Variant::scale), nullptr);

    gate.open();
    const BuiltPipeline* scale = poll_until_built(cache, Variant::scale, builds);
    ASSERT_NE(scale, nullptr) << "still building after 30 s";
    ASSERT_NE(scale, turn);
    EXPECT_EQ(scale, cache.find(Variant::scale));

    // A variant that fails: the one returned last (now `scale`) stays, before and after the failure.
    const auto failed_by = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!cache.failed(Variant::broken) && std::chrono::steady_clock::now() < failed_by) {
        EXPECT_EQ(cache.request_or_last(*device_, Variant::broken, builds.of(Variant::broken)), scale);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_TRUE(cache.failed(Variant::broken));
    EXPECT_EQ(cache.request_or_last(*device_, Variant::broken, builds.of(Variant::broken)), scale);
    EXPECT_EQ(errors.count("wave_step.frag:"), 1);
    EXPECT_EQ(builds.count, 3) << "each variant built once";
}

TEST_F(PipelineCacheTest, AFailureOfWhatAPassNeedsBesidesItsShaderIsLikeAFailedBuild) {
    const ErrorLines errors;
    render::SinglePipelineCache cache("drawing nothing");
    int builds = 0;
    const auto make = [&] {
        ++builds;
        return desc_of(Variant::turn);
    };
    cache.fail({}, make_error(ExitCode::GpuMemory, "gpu: texture 'data': GL_OUT_OF_MEMORY"));
    cache.fail({}, make_error(ExitCode::GpuMemory, "gpu: texture 'data': GL_OUT_OF_MEMORY"));
    EXPECT_EQ(cache.request(*device_, {}, make), nullptr);
    EXPECT_TRUE(cache.failed({}));
    EXPECT_EQ(builds, 0);
    EXPECT_EQ(errors.count("gpu: texture 'data': GL_OUT_OF_MEMORY (drawing nothing)"), 1);
}

}  // namespace
}  // namespace puddle::test
