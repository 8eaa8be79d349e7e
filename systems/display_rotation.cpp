#include "systems/display_rotation.hpp"

#include <spdlog/spdlog.h>

namespace puddle::systems {

gpu::FrameTarget begin_rotated_frame(gpu::Device& device, const params::Params& params, DisplayRotation& r,
                                     gpu::FrameTarget display) {
    r.display = display;
    const int degrees = std::stoi(params.s(params::ParamId::display_rotation));
    r.quarter_turns = degrees / 90;
    if (r.quarter_turns == 0) return display;
    const glm::ivec2 size = r.quarter_turns % 2 ? glm::ivec2(display.size.y, display.size.x) : display.size;
    if (size != r.canvas_size) {
        if (r.pipeline.id() == 0) {
            auto pipeline = device.create_pipeline({.label = "rotate", .fragment = "rotate.frag", .textures = {"u_canvas"}});
            if (!pipeline) {
                spdlog::error("{} (showing the picture unturned)", pipeline.error().message);
                r.quarter_turns = 0;
                return display;
            }
            r.pipeline = std::move(*pipeline);
            r.sampler = device.create_sampler({.label = "canvas", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
        }
        r.canvas = device.create_texture(
            {.label = "rotation canvas", .format = gpu::TextureFormat::RGBA8, .width = size.x, .height = size.y});
        r.canvas_size = size;
        spdlog::info("display: turned {} degrees clockwise; the picture renders at {}x{}", degrees, size.x, size.y);
    }
    return {&r.canvas, size};
}

void rotation_system(gpu::Device& device, const DisplayRotation& r) {
    if (r.quarter_turns == 0) return;
    auto pass = device.begin_pass({.label = "rotate", .target = r.display, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(r.pipeline).set_texture(0, r.canvas, r.sampler).set("u_quarter_turns", r.quarter_turns);
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
