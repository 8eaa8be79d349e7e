#include "systems/output/output_canvas.hpp"

#include <spdlog/spdlog.h>

#include <utility>

namespace puddle::systems {

namespace {

CanvasPass canvas_pass(bool scaled) {
    return scaled ? CanvasPass::turn_and_scale : CanvasPass::turn;
}

gpu::PipelineDesc canvas_desc(CanvasPass pass) {
    if (pass == CanvasPass::turn)
        return {.label = "rotate", .fragment = "output_canvas.frag", .textures = {"u_canvas"}};
    return {.label = "upscale",
            .fragment = "output_canvas.frag",
            .defines = {"SCALED"},
            .textures = {"u_canvas"}};
}

// The canvas for these parameters on a screen of `display_size`.
struct CanvasLayout {
    int degrees = 0;
    glm::ivec2 size{0, 0};
    bool scaled = false;
    float brightness = 1;  // display.brightness: below 1 the last pass dims the picture
    bool needed() const { return degrees != 0 || scaled || brightness < 1; }
};

CanvasLayout canvas_layout(const params::Params& params, glm::ivec2 display_size, float scale) {
    CanvasLayout l;
    // wall.rotation turns a screen of a video wall the same way (docs/video-walls.md, portrait screens).
    const int quarter_turns = static_cast<int>(params.get<params::ParamId::display_rotation>()) +
                              params.get<params::ParamId::wall_rotation>();
    l.degrees = 90 * (quarter_turns % 4);
    const glm::ivec2 turned = l.degrees % 180 ? glm::ivec2(display_size.y, display_size.x) : display_size;
    l.size = glm::max(glm::ivec2(glm::round(glm::vec2(turned) * scale)), glm::ivec2(1));
    l.scaled = l.size != turned;
    l.brightness = params.get<params::ParamId::display_brightness>();
    return l;
}

}  // namespace

Result<void> prepare_output_canvas(gpu::Device& device, const params::Params& params, OutputCanvas& canvas,
                                   glm::ivec2 display_size) {
    const CanvasLayout l = canvas_layout(params, display_size, params.get<params::ParamId::render_scale>());
    if (!l.needed()) return {};
    const CanvasPass pass = canvas_pass(l.scaled);
    return canvas.pipelines.ensure(device, pass, [&] { return canvas_desc(pass); });
}

gpu::FrameTarget begin_canvas_frame(gpu::Device& device, const params::Params& params, OutputCanvas& r,
                                    gpu::FrameTarget display, float scale) {
    r.display = display;
    const CanvasLayout l = canvas_layout(params, display.size, scale);
    const int degrees = l.degrees;
    const glm::ivec2 size = l.size;
    r.quarter_turns = degrees / 90;
    r.scaled = l.scaled;
    r.brightness = l.brightness;
    if (!l.needed()) return display;
    const CanvasPass pass = canvas_pass(r.scaled);
    const bool ready = r.pipelines.request(device, pass, [&] { return canvas_desc(pass); }) != nullptr;
    if (ready && r.sampler.id() == 0) {
        r.sampler = device.create_sampler(
            {.label = "canvas", .min = gpu::Filter::Nearest, .mag = gpu::Filter::Nearest});
        r.smooth = device.create_sampler({.label = "canvas (scaled)"});
    }
    if (ready && size != r.canvas_size && size != r.failed_size) {
        auto canvas = device.create_texture({.label = "canvas",
                                             .format = gpu::TextureFormat::RGBA8,
                                             .width = size.x,
                                             .height = size.y,
                                             .render_target = true});
        if (canvas) {
            r.canvas = std::move(canvas).value();
            r.canvas_size = size;
            // The adaptive scale resizes the canvas every few seconds while it looks for its scale and says
            // where it settled itself; a new screen size or turn is worth the info line.
            const bool new_layout = std::exchange(r.logged_layout, glm::ivec3(display.size, degrees)) !=
                                    glm::ivec3(display.size, degrees);
            spdlog::log(new_layout ? spdlog::level::info : spdlog::level::debug,
                        "display: {}x{}, turned {} degrees clockwise; the picture renders at {}x{}{}{}",
                        display.size.x, display.size.y, degrees, size.x, size.y,
                        r.scaled ? " and is scaled up" : "",
                        r.brightness < 1 ? "; dimmed in the last pass" : "");
        } else {
            // The old canvas has the wrong size for this frame: the scene renders straight to the display.
            spdlog::error("{} (showing the picture unturned, at full size)", canvas.error().message);
            r.failed_size = size;
        }
    }
    if (!ready || size == r.failed_size) {
        r.quarter_turns = 0;
        r.scaled = false;
        r.brightness = 1;
        return display;
    }
    return {&r.canvas, size};
}

void output_canvas_system(gpu::Device& device, const OutputCanvas& r) {
    if (r.quarter_turns == 0 && !r.scaled && r.brightness >= 1) return;
    const render::BuiltPipeline* built = r.pipelines.find(canvas_pass(r.scaled));
    if (!built) return;  // begin_canvas_frame rendered the scene to the display then
    auto pass = device.begin_pass(
        {.label = r.scaled ? "upscale" : "rotate", .target = r.display, .load = gpu::LoadOp::DontCare});
    pass.set_pipeline(built->pipeline);
    if (r.scaled)
        pass.set_texture(0, r.canvas, r.smooth).set("u_screen_size", glm::vec2(r.display.size));
    else
        pass.set_texture(0, r.canvas, r.sampler);
    pass.set("u_quarter_turns", r.quarter_turns);
    pass.set("u_brightness", r.brightness);
    pass.draw_fullscreen();
}

}  // namespace puddle::systems
