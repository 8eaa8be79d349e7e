#pragma once
// A pipeline built the first time its system is chosen, so scenes and models nobody selects cost no
// shader compiles at start-up, and a scene switched on at run time still works. A failed build logs one
// line, once, and the system then draws nothing instead of retrying every frame.

#include <spdlog/spdlog.h>

#include "gpu/device.hpp"

namespace puddle::systems {

struct LazyPipeline {
    gpu::Pipeline pipeline;
    bool failed = false;

    bool ready() const { return pipeline.id() != 0; }

    // make_desc is called only when a build is due, so the steady state allocates nothing.
    template <class MakeDesc>
    Result<void> ensure(gpu::Device& device, MakeDesc&& make_desc) {
        if (ready()) return {};
        if (failed) return make_error(ExitCode::Runtime, "gpu: pipeline failed to build before");
        auto p = device.create_pipeline(make_desc());
        if (!p) {
            failed = true;
            return p.error();
        }
        pipeline = std::move(p).value();
        return {};
    }

    // For systems in the frame loop: true when the pipeline can be used.
    template <class MakeDesc>
    bool ensure_or_log(gpu::Device& device, MakeDesc&& make_desc) {
        const bool was_failed = failed;
        if (auto r = ensure(device, std::forward<MakeDesc>(make_desc)); !r) {
            if (!was_failed) spdlog::error("{}", r.error().message);
            return false;
        }
        return true;
    }
};

}  // namespace puddle::systems
