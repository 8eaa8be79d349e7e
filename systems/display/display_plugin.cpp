#include "systems/display/display_plugin.hpp"

#include <spdlog/spdlog.h>

#include <glm/common.hpp>
#include <utility>

#include "ecs/frame_time.hpp"
#include "render/view_window.hpp"

namespace puddle::systems {

void begin_frame_system(platform::Display& display, gpu::Device& device, const params::Params& params,
                        const AdaptiveScale& adaptive, OutputCanvas& canvas, RenderTarget& target) {
    display.make_current();  // another engine, or a test, may have made its own current since
    const gpu::FrameTarget screen = display.frame_target();
    target.target = systems::begin_canvas_frame(device, params, canvas, screen, adaptive.scale);
    // The wall's bezels are in the screen's pixels, and its tiles are upright: the screen turned as the
    // picture is (not at all when the canvas could not be made), whatever render.scale is.
    const glm::ivec2 upright =
        canvas.quarter_turns % 2 ? glm::ivec2(screen.size.y, screen.size.x) : screen.size;
    const render::ViewWindow window = render::wall_window(params, glm::vec2(upright));
    if (window != target.view && window != render::ViewWindow{}) {  // said at start-up and at each change
        const glm::vec2 view = window.view_size(upright);
        // Rounded, and + 0 so that the top row is at 0, not -0.
        const glm::vec2 corner =
            glm::round(glm::vec2(window.origin.x, 1.0f - window.origin.y - window.extent.y) * view) + 0.0f;
        spdlog::info(
            "wall: this screen shows {}x{} pixels at ({:.0f}, {:.0f}) from the top left of the "
            "{:.0f}x{:.0f} view",
            upright.x, upright.y, corner.x, corner.y, view.x, view.y);
        // Valid but almost surely a mistake: a bezel is the gap between two pictures in this screen's
        // pixels (both frames together, a few dozen pixels), not the wall's size or millimetres.
        const float bezel_x = params.get<params::ParamId::wall_bezel_x>();
        const float bezel_y = params.get<params::ParamId::wall_bezel_y>();
        if (bezel_x > static_cast<float>(upright.x) || bezel_y > static_cast<float>(upright.y))
            spdlog::warn(
                "wall: wall.bezel_x = {:g}, wall.bezel_y = {:g} pixels: a bezel wider than this {}x{} screen "
                "hides more of the picture than a screen shows; bezels are the gap between two pictures in "
                "this screen's pixels (docs/video-walls.md)",
                bezel_x, bezel_y, upright.x, upright.y);
    }
    target.view = window;
}

assets::Image read_display(platform::Display& display, gpu::Device& device) {
    display.make_current();
    const gpu::FrameTarget target = display.frame_target();
    assets::Image image = assets::Image::make(target.size.x, target.size.y);
    device.read_pixels(target, image.data);
    return image;
}

void capture_system(platform::Display& display, gpu::Device& device, FrameCapture& capture) {
    if (!capture.requested) return;
    capture.requested = false;
    capture.image = read_display(display, device);  // before present: a window or KMS may not keep the frame
}

void present_system(platform::Display& display, OutputPower& power, PresentStatus& status) {
    if (!power.on && !std::exchange(power.black_frame_pending, false)) {
        status.result = {};
        return;
    }
    status.result = display.present();
}

Result<void> add_display_plugin(ecs::World& world, ecs::Schedule& schedule) {
    world.insert_resource<ecs::FrameTime>();
    world.insert_resource<RenderTarget>();
    auto& adaptive = world.insert_resource<AdaptiveScale>();
    adaptive.display_refresh_hz = world.resource<platform::Display>().refresh_hz();
    adaptive.scale = world.resource<params::Params>().get<params::ParamId::render_scale>();
    auto& canvas = world.insert_resource<OutputCanvas>();
    if (auto r =
            systems::prepare_output_canvas(world.resource<gpu::Device>(), world.resource<params::Params>(),
                                           canvas, world.resource<platform::Display>().frame_target().size);
        !r)
        return r;
    world.insert_resource<OutputPower>();
    world.insert_resource<FrameCapture>();
    world.insert_resource<PresentStatus>();
    using ecs::Stage;
    schedule.add(Stage::Input, "begin frame", begin_frame_system);
    schedule.add(Stage::Input, "gpu timer begin", systems::gpu_timer_begin_system).run_if(output_on());
    schedule.add(Stage::Present, "output canvas", systems::output_canvas_system).run_if(output_on());
    schedule.add(Stage::Present, "adaptive scale", systems::adaptive_scale_system).run_if(output_on());
    schedule.add(Stage::Present, "capture", capture_system);
    schedule.add(Stage::Present, "present", present_system);
    return {};
}

}  // namespace puddle::systems
