#pragma once
// A pipeline built the first time its system is chosen, so scenes and models nobody selects cost no
// shader compiles at start-up, and a look switched on at run time still works. At start-up `ensure`
// builds at once (a broken shader stops start-up with its message); in the frame loop `request` has it
// built off the frame thread (Device::request_pipeline) and says when it is ready, so the old picture
// stays on screen meanwhile. A failed build logs one line, once, and is not tried again.

#include <spdlog/spdlog.h>

#include "gpu/device.hpp"
#include "render/param_uniforms.hpp"

namespace puddle::render {

struct LazyPipeline {
    gpu::Pipeline pipeline;
    ParamBinding params;            // the parameters its shader reads (render/param_uniforms.hpp)
    gpu::PipelineRequest building;  // a request in flight
    bool failed = false;

    bool ready() const { return pipeline.id() != 0; }

    // Builds it now, waiting for the compile. make_desc is called only when a build is due, so the
    // steady state allocates nothing.
    template <class MakeDesc>
    Result<void> ensure(gpu::Device& device, MakeDesc&& make_desc) {
        if (ready()) return {};
        if (failed) return make_error(ExitCode::Runtime, "gpu: pipeline failed to build before");
        building = {};
        return keep(device.create_pipeline(make_desc()));
    }

    // For systems in the frame loop: true when the pipeline can be used. Otherwise starts (or checks on)
    // a build that does not block; a failure is logged once.
    template <class MakeDesc>
    bool request(gpu::Device& device, MakeDesc&& make_desc) {
        if (ready()) return true;
        if (failed) return false;
        if (!building.active()) building = device.request_pipeline(make_desc());
        auto built = device.take_pipeline(building);
        if (!built) return false;
        if (auto r = keep(std::move(*built)); !r) {
            spdlog::error("{}", r.error().message);
            return false;
        }
        return true;
    }

private:
    Result<void> keep(Result<gpu::Pipeline> built) {
        auto binding = built ? bind_params(*built) : Result<ParamBinding>(built.error());
        if (!binding) {
            failed = true;
            return binding.error();
        }
        pipeline = std::move(built).value();
        params = std::move(binding).value();
        return {};
    }
};

}  // namespace puddle::render
