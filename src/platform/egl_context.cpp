#include "platform/egl_context.hpp"

#include <cstring>
#include <map>
#include <utility>
#include <vector>

#include "gpu/gl_extensions.hpp"
#include "platform/display.hpp"

namespace puddle::platform {

namespace {

// The extension table (gpu/gl_extensions.hpp) as it is before any display exists: its client entries,
// EGL_EXT_platform_base, are what making a display and a window surface need. Looked up once.
const gpu::GlExtensions& client_extensions() {
    static const gpu::GlExtensions table = gpu::GlExtensions::load();
    return table;
}

// How many EglContexts use each initialised display.
std::map<EGLDisplay, int>& display_users() {
    static std::map<EGLDisplay, int> users;
    return users;
}

const char* platform_name(EGLenum platform) {
    switch (platform) {
        case EGL_PLATFORM_SURFACELESS_MESA:
            return "surfaceless";
        case EGL_PLATFORM_GBM_KHR:
            return "gbm";
        case EGL_PLATFORM_X11_KHR:
            return "x11";
        default:
            return "default";
    }
}

}  // namespace

const char* egl_error_name(EGLint error) {
    switch (error) {
        case EGL_SUCCESS:
            return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CURRENT_SURFACE:
            return "EGL_BAD_CURRENT_SURFACE";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_SURFACE:
            return "EGL_BAD_SURFACE";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        case EGL_BAD_NATIVE_PIXMAP:
            return "EGL_BAD_NATIVE_PIXMAP";
        case EGL_BAD_NATIVE_WINDOW:
            return "EGL_BAD_NATIVE_WINDOW";
        case EGL_CONTEXT_LOST:
            return "EGL_CONTEXT_LOST";
        default:
            return "EGL error";
    }
}

Result<EglContext> EglContext::create(const EglRequest& request) {
    const char* pname = platform_name(request.platform);
    const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    EglContext ctx;
    if (request.platform != 0) {
        if (!client_extensions().eglGetPlatformDisplayEXT)
            return make_error(ExitCode::Display,
                              "egl: eglGetPlatformDisplayEXT missing (client extensions: {})",
                              client_ext ? client_ext : "none");
        ctx.display_ =
            client_extensions().eglGetPlatformDisplayEXT(request.platform, request.native_display, nullptr);
    } else {
        ctx.display_ = eglGetDisplay(static_cast<EGLNativeDisplayType>(request.native_display));
    }
    if (ctx.display_ == EGL_NO_DISPLAY)
        return make_error(ExitCode::Display, "egl: {}: no EGL display: {}", pname,
                          egl_error_name(eglGetError()));
    EGLint major = 0, minor = 0;
    if (!eglInitialize(ctx.display_, &major, &minor)) {
        ctx.display_ = EGL_NO_DISPLAY;  // nothing to terminate
        return make_error(ExitCode::Display, "egl: {}: eglInitialize: {}", pname,
                          egl_error_name(eglGetError()));
    }
    ++display_users()[ctx.display_];
    if (const char* ext = eglQueryString(ctx.display_, EGL_EXTENSIONS)) ctx.extensions_ = ext;
    if (!eglBindAPI(EGL_OPENGL_ES_API))
        return make_error(ExitCode::Display, "egl: {}: eglBindAPI(GLES): {}", pname,
                          egl_error_name(eglGetError()));

    const EGLint attribs[] = {EGL_SURFACE_TYPE,
                              request.window_surface ? EGL_WINDOW_BIT : 0,
                              EGL_RED_SIZE,
                              8,
                              EGL_GREEN_SIZE,
                              8,
                              EGL_BLUE_SIZE,
                              8,
                              EGL_ALPHA_SIZE,
                              0,
                              EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_ES3_BIT,
                              EGL_NONE};
    EGLint count = 0;
    eglChooseConfig(ctx.display_, attribs, nullptr, 0, &count);
    std::vector<EGLConfig> configs(static_cast<std::size_t>(count));
    if (count > 0) eglChooseConfig(ctx.display_, attribs, configs.data(), count, &count);
    for (EGLConfig c : configs) {
        EGLint visual = 0;
        eglGetConfigAttrib(ctx.display_, c, EGL_NATIVE_VISUAL_ID, &visual);
        if (request.native_visual == 0 || visual == request.native_visual) {
            ctx.config_ = c;
            break;
        }
    }
    // Surfaceless contexts need no config at all where EGL_KHR_no_config_context exists.
    if (!ctx.config_ && (request.window_surface || !ctx.has_extension("EGL_KHR_no_config_context")))
        return make_error(ExitCode::Display, "egl: {}: no GLES 3 config{} ({} candidates)", pname,
                          request.native_visual ? " matching the scan-out format" : "", count);

    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    ctx.context_ = eglCreateContext(ctx.display_, ctx.config_ ? ctx.config_ : EGL_NO_CONFIG_KHR,
                                    EGL_NO_CONTEXT, context_attribs);
    if (ctx.context_ == EGL_NO_CONTEXT)
        return make_error(ExitCode::Display, "egl: {}: cannot create a GLES 3 context: {}", pname,
                          egl_error_name(eglGetError()));
    return ctx;
}

EglContext::EglContext(EglContext&& other) noexcept {
    *this = std::move(other);
}

EglContext& EglContext::operator=(EglContext&& other) noexcept {
    if (this != &other) {
        release();
        display_ = std::exchange(other.display_, EGL_NO_DISPLAY);
        config_ = std::exchange(other.config_, nullptr);
        context_ = std::exchange(other.context_, EGL_NO_CONTEXT);
        surface_ = std::exchange(other.surface_, EGL_NO_SURFACE);
        extensions_ = std::move(other.extensions_);
    }
    return *this;
}

EglContext::~EglContext() {
    release();
}

void EglContext::release() {
    if (display_ == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    // One EGLDisplay is shared by every context on the same platform in this process (an engine in a
    // test beside another, a benchmark's engines): terminate it only when the last user goes.
    if (--display_users()[display_] == 0) {
        display_users().erase(display_);
        eglTerminate(display_);
    }
    display_ = EGL_NO_DISPLAY;
    surface_ = EGL_NO_SURFACE;
    context_ = EGL_NO_CONTEXT;
}

Result<void> EglContext::attach_window(void* native_window) {
    if (client_extensions().eglCreatePlatformWindowSurfaceEXT)
        surface_ =
            client_extensions().eglCreatePlatformWindowSurfaceEXT(display_, config_, native_window, nullptr);
    else
        surface_ = eglCreateWindowSurface(display_, config_,
                                          reinterpret_cast<EGLNativeWindowType>(native_window), nullptr);
    if (surface_ == EGL_NO_SURFACE)
        return make_error(ExitCode::Display, "egl: cannot create a window surface: {}",
                          egl_error_name(eglGetError()));
    if (!eglMakeCurrent(display_, surface_, surface_, context_))
        return make_error(ExitCode::Display, "egl: eglMakeCurrent(window): {}",
                          egl_error_name(eglGetError()));
    return {};
}

Result<void> EglContext::make_current_surfaceless() {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
        return make_error(ExitCode::Display, "egl: eglMakeCurrent(surfaceless): {}",
                          egl_error_name(eglGetError()));
    return {};
}

Result<void> EglContext::make_current() {
    if (!eglMakeCurrent(display_, surface_, surface_, context_))
        return make_error(ExitCode::Display, "egl: eglMakeCurrent: {}", egl_error_name(eglGetError()));
    return {};
}

namespace {

class SharedEglContext final : public gpu::WorkerContext {
public:
    SharedEglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {
        ++display_users()[display_];
    }
    ~SharedEglContext() override {
        eglDestroyContext(display_, context_);
        if (--display_users()[display_] == 0) {
            display_users().erase(display_);
            eglTerminate(display_);
        }
    }
    Result<void> make_current() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            return make_error(ExitCode::Display, "egl: eglMakeCurrent(worker context): {}",
                              egl_error_name(eglGetError()));
        return {};
    }
    void release() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

private:
    EGLDisplay display_;
    EGLContext context_;
};

}  // namespace

Result<std::unique_ptr<gpu::WorkerContext>> EglContext::create_worker_context() const {
    if (!has_extension("EGL_KHR_surfaceless_context"))
        return make_error(ExitCode::Display, "egl: no EGL_KHR_surfaceless_context for a worker context");
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
    const EGLContext shared =
        eglCreateContext(display_, config_ ? config_ : EGL_NO_CONFIG_KHR, context_, context_attribs);
    if (shared == EGL_NO_CONTEXT)
        return make_error(ExitCode::Display, "egl: cannot create a worker context: {}",
                          egl_error_name(eglGetError()));
    return std::unique_ptr<gpu::WorkerContext>(std::make_unique<SharedEglContext>(display_, shared));
}

bool EglContext::swap_buffers() {
    return eglSwapBuffers(display_, surface_) == EGL_TRUE;
}

bool EglContext::has_extension(std::string_view name) const {
    if (name.empty()) return false;  // it would match everywhere and never advance
    std::size_t pos = 0;
    while ((pos = extensions_.find(name, pos)) != std::string::npos) {
        const std::size_t end = pos + name.size();
        if ((pos == 0 || extensions_[pos - 1] == ' ') &&
            (end == extensions_.size() || extensions_[end] == ' '))
            return true;
        pos = end;
    }
    return false;
}

std::string EglContext::vendor() const {
    const char* v = eglQueryString(display_, EGL_VENDOR);
    return v ? v : "unknown";
}

bool current_display_has_extension(std::string_view name) {
    const EGLDisplay display = eglGetCurrentDisplay();
    const char* list = display == EGL_NO_DISPLAY ? nullptr : eglQueryString(display, EGL_EXTENSIONS);
    if (!list || name.empty()) return false;  // an empty name would match a trailing space
    const std::string_view all(list);
    for (std::size_t at = all.find(name); at != std::string_view::npos; at = all.find(name, at + 1)) {
        const bool starts = at == 0 || all[at - 1] == ' ';
        const bool ends = at + name.size() == all.size() || all[at + name.size()] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

}  // namespace puddle::platform
