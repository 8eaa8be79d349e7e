#include "systems/output_canvas.hpp"

#include <spdlog/spdlog.h>

namespace puddle::systems {

namespace {

Result<void> build_pipelines(gpu::Device& device, OutputCanvas& r) {
    auto exact = device.create_pipeline(
        {.label = "rotate", .fragment = "output_canvas.frag", .textures = {"u_canvas"}});
    if (!exact) return exact.error();
    auto upscale = device.create_pipeline({.label = "upscale",
                                           .fragment = "output_canvas.frag",
                                           .defines = {"SCALED"},
                                           .textures = {"u_canvas"}});
    if (!upscale) return upscale.error();
    r.pipeline = std::move(*exact);
    r.upscale = std::move(*upscale);
    r.sampler =
        device.create_sampler({.label = "canvas", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
    r.smooth = device.create_sampler({.label = "canvas (scaled)"});
    return {};
}

}  // namespace

gpu::FrameTarget begin_canvas_frame(gpu::Device& device, const params::Params& params, OutputCanvas& r,
                                    gpu::FrameTarget display) {
    r.display = display;
    const int degrees = 90 * static_cast<int>(params.get<params::ParamId::display_rotation>());
    const float scale = params.get<params::ParamId::render_scale>();
    r.quarter_turns = degrees / 90;
    const glm::ivec2 turned = r.quarter_turns % 2 ? glm::ivec2(display.size.y, display.size.x) : display.size;
    const glm::ivec2 size = glm::max(glm::ivec2(glm::round(glm::vec2(turned) * scale)), glm::ivec2(1));
    r.scaled = size != turned;
    if (r.quarter_turns == 0 && !r.scaled) return display;
    if (!r.unavailable && r.pipeline.id() == 0) {
        if (auto built = build_pipelines(device, r); !built) {
            spdlog::error("{} (showing the picture unturned, at full size)", built.error().message);
            r.unavailable = true;  // a shader that failed once fails every frame: no error 60 times a second
        }
    }
    if (!r.unavailable && size != r.canvas_size && size != r.failed_size) {
        auto canvas = device.create_texture({.label = "canvas",
                                             .format = gpu::TextureFormat::RGBA8,
                                             .width = size.x,
                                             .height = size.y,
                                             .render_target = true});
        if (canvas) {
            r.canvas = std::move(canvas).value();
            r.canvas_size = size;
            spdlog::info("display: {}x{}, turned {} degrees clockwise; the picture renders at {}x{}{}",
                         display.size.x, display.size.y, degrees, size.x, size.y,
                         r.scaled ? " and is scaled up" : "");
        } else {
            // The old canvas has the wrong size for this frame: the scene renders straight to the display.
            spdlog::error("{} (showing the picture unturned, at full size)", canvas.error().message);
            r.failed_size = size;
        }
    }
    if (r.unavailable || size == r.failed_size) {
        r.quarter_turns = 0;
        r.scaled = false;
        return display;
    }
    return {&r.canvas, size};
}

void output_canvas_system(gpu::Device& device, const OutputCanvas& r) {
    if (r.quarter_turns == 0 && !r.scaled) return;
    auto pass = device.begin_pass(
        {.label = r.scaled ? "upscale" : "rotate", .target = r.display, .load = gpu::LoadOp::DontCare});
    if (r.scaled)
        pass.set_pipeline(r.upscale)
            .set_texture(0, r.canvas, r.smooth)
            .set("u_screen_size", glm::vec2(r.display.size));
    else
        pass.set_pipeline(r.pipeline).set_texture(0, r.canvas, r.sampler);
    pass.set("u_quarter_turns", r.quarter_turns);
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
