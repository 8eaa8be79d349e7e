#pragma once
// An EGL display + GLES 3 context, shared by every backend. Private to src/platform (it includes EGL);
// extension entry points come from the one table, gpu/gl_extensions.hpp. Move-only; the destructor releases
// the context, surfaces and the display connection.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <memory>
#include <string>
#include <string_view>

#include "gpu/worker_context.hpp"
#include "util/result.hpp"

namespace puddle::platform {

struct EglRequest {
    EGLenum platform = 0;  // EGL_PLATFORM_SURFACELESS_MESA, EGL_PLATFORM_GBM_KHR, EGL_PLATFORM_X11_KHR
    void* native_display = nullptr;  // gbm_device*, Display* (X11), or EGL_DEFAULT_DISPLAY
    bool window_surface = false;     // need an EGLConfig usable with a window surface
    EGLint native_visual = 0;        // GBM: the format the config must match (GBM_FORMAT_XRGB8888), 0 = any
};

class EglContext {
public:
    static Result<EglContext> create(const EglRequest& request);
    EglContext() = default;
    EglContext(EglContext&& other) noexcept;
    EglContext& operator=(EglContext&& other) noexcept;
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;
    ~EglContext();

    // Makes a window surface for native_window (gbm_surface*, X11 Window) and makes it current.
    Result<void> attach_window(void* native_window);
    // Current with no surface at all (headless renders into FBOs).
    Result<void> make_current_surfaceless();
    bool swap_buffers();
    // Makes this context (and its window surface, if any) current again.
    Result<void> make_current();

    EGLDisplay display() const { return display_; }
    EGLConfig config() const { return config_; }
    EGLContext context() const { return context_; }
    EGLSurface surface() const { return surface_; }
    bool has_extension(std::string_view name) const;  // display extensions, whole words; false for ""
    // A context sharing this one's objects, for a worker thread (gpu/worker_context.hpp). Needs
    // EGL_KHR_surfaceless_context (Mesa has it on every platform); an error says what is missing. Create
    // and destroy it on this context's thread; only make_current/release run on the worker.
    Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() const;
    std::string vendor() const;

private:
    void release();
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLConfig config_ = nullptr;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
    std::string extensions_;
};

// eglGetError() as a name, for messages: "EGL_BAD_MATCH".
const char* egl_error_name(EGLint error);

}  // namespace puddle::platform
