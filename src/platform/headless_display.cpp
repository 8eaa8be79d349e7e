// Headless backend: EGL on Mesa's surfaceless platform, rendering into an offscreen texture that tests,
// screenshots and benchmarks read back. No window system, no DRM device needed.

#include <fmt/format.h>

#include <memory>

#include "gpu/device.hpp"
#include "gpu/gl.hpp"
#include "platform/display.hpp"
#include "platform/egl_context.hpp"

namespace puddle::platform {

namespace {

class HeadlessDisplay final : public Display {
public:
    HeadlessDisplay(EglContext context, glm::ivec2 size) : context_(std::move(context)), size_(size) {}

    Result<void> prepare(gpu::Device& device) override {
        auto target = device.create_texture({.label = "headless frame",
                                             .format = gpu::TextureFormat::RGBA8,
                                             .width = size_.x,
                                             .height = size_.y,
                                             .render_target = true});
        if (!target) return target.error();
        target_ = std::move(target).value();
        return {};
    }

    void make_current() override { (void)context_.make_current_surfaceless(); }
    Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() override {
        return context_.create_worker_context();
    }
    BackendKind kind() const override { return BackendKind::Headless; }
    bool shows_frames() const override { return false; }
    glm::ivec2 size() const override { return size_; }
    gpu::FrameTarget frame_target() const override { return {&target_, size_}; }
    bool poll_events() override { return true; }
    // Nothing to show, but paced like a swap chain two frames deep: wait until the frame before this one
    // is done on the GPU. A bare glFlush let llvmpipe queue dozens of slow frames (the ocean) and then
    // block for all of them at once, 5 to 11 s without a watchdog ping.
    Result<void> present() override {
        GLsync done = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        glFlush();
        if (in_flight_) {
            glClientWaitSync(in_flight_, 0, GL_TIMEOUT_IGNORED);  // a hung GPU: the watchdog's case
            glDeleteSync(in_flight_);
        }
        in_flight_ = done;
        return {};
    }
    ~HeadlessDisplay() override {
        if (in_flight_) {
            (void)context_.make_current_surfaceless();
            glDeleteSync(in_flight_);
        }
    }
    std::string describe() const override {
        return fmt::format("headless: EGL surfaceless ({}) {}x{}", context_.vendor(), size_.x, size_.y);
    }

private:
    EglContext context_;
    glm::ivec2 size_;
    gpu::Texture target_;
    GLsync in_flight_ = nullptr;  // the previous frame's fence
};

}  // namespace

Result<std::unique_ptr<Display>> create_headless_display(const DisplayOptions& options) {
    auto context = EglContext::create({.platform = EGL_PLATFORM_SURFACELESS_MESA,
                                       .native_display = EGL_DEFAULT_DISPLAY,
                                       .window_surface = false,
                                       .native_visual = 0});
    if (!context) return make_error(ExitCode::Display, "headless: {}", context.error().message);
    if (auto r = context->make_current_surfaceless(); !r)
        return make_error(ExitCode::Display, "headless: {}", r.error().message);
    const glm::ivec2 size = options.size.x > 0 && options.size.y > 0 ? options.size : glm::ivec2(640, 360);
    return std::unique_ptr<Display>(std::make_unique<HeadlessDisplay>(std::move(context).value(), size));
}

}  // namespace puddle::platform
