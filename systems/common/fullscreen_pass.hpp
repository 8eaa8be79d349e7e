#pragma once
// A pass drawn as one fullscreen triangle over view_window.vert (the ocean, the street), or by its own
// draw call over the same view window (the rain overlay's quads): its pipeline, built at start-up or off
// the frame thread on first use, and the set-up every such pass shares (its pipeline, the parameter
// uniforms, u_view_window).

#include <utility>

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/param_uniforms.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/render_target.hpp"
#include "util/result.hpp"

namespace puddle::systems {

struct FullscreenPass {
    gpu::PipelineDesc desc;  // its label names the pass in logs and GPU debuggers
    render::SinglePipelineCache cache;

    explicit FullscreenPass(gpu::PipelineDesc d) : desc(std::move(d)) {}

    // Builds the pipeline now (start-up): a broken shader stops start-up with its message.
    Result<void> prepare(gpu::Device& device) {
        return cache.ensure(device, {}, [this] { return desc; });
    }
    // Has it built off the frame thread; true once ready.
    bool request(gpu::Device& device) {
        return cache.request(device, {}, [this] { return desc; }) != nullptr;
    }

    // Draws the pass into `target` once its pipeline is built (nothing until then): sets the pipeline,
    // the parameter uniforms and u_view_window, then `set_uniforms(pass)` sets the pass's own.
    // A template, not a std::function, so that drawing allocates nothing.
    template <class SetUniforms>
    void draw(gpu::Device& device, const params::Params& params, const RenderTarget& target, gpu::LoadOp load,
              SetUniforms&& set_uniforms) {
        draw_with(device, params, target, load, set_uniforms,
                  [](gpu::RenderPass& pass) { pass.draw_fullscreen(); });
    }
    // The same with the pass's own draw call (the rain streaks: a quad per streak) instead of the triangle.
    template <class SetUniforms, class Draw>
    void draw_with(gpu::Device& device, const params::Params& params, const RenderTarget& target,
                   gpu::LoadOp load, SetUniforms&& set_uniforms, Draw&& draw_call) {
        const render::BuiltPipeline* built = cache.request(device, {}, [this] { return desc; });
        if (!built) return;
        auto pass = device.begin_pass({.label = desc.label, .target = target.target, .load = load});
        pass.set_pipeline(built->pipeline);
        render::set_param_uniforms(pass, built->params, params);
        pass.set("u_view_window", target.view.uniform());
        set_uniforms(pass);
        draw_call(pass);
    }
};

// The Looks entry of a scene drawn by `pass` alone (the ocean, the street): its pass is all it builds.
inline LookEntry fullscreen_look(Scene scene, FullscreenPass& pass) {
    return {.scene = scene,
            .prepare = [&pass](gpu::Device& d) { return pass.prepare(d); },
            .request = [&pass](gpu::Device& d) { return pass.request(d); }};
}

}  // namespace puddle::systems
