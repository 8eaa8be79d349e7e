// A desktop window through EGL on X11: for development on a workstation and for kiosks that run X.
// Closing the window (WM_DELETE_WINDOW) ends the run loop; fullscreen asks the window manager through
// _NET_WM_STATE and also covers the screen itself, for X servers that run without one.

#include <fmt/format.h>
#include <poll.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <utility>

#include "platform/display.hpp"
#include "platform/egl_context.hpp"

// Xlib last: its macros (None, Bool, Status, ...) would otherwise leak into the headers above.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace puddle::platform {

namespace {

struct CloseXDisplay {
    void operator()(::Display* x) const { XCloseDisplay(x); }
};
using XDisplayPtr = std::unique_ptr<::Display, CloseXDisplay>;

struct FreeX {
    void operator()(void* p) const { XFree(p); }
};

// An X resource (window, colormap, cursor) freed with Free(display, id).
template <auto Free>
class XHandle {
public:
    XHandle() = default;
    XHandle(::Display* x, XID id) : x_(x), id_(id) {}
    XHandle(XHandle&& other) noexcept : x_(other.x_), id_(std::exchange(other.id_, 0)) {}
    XHandle& operator=(XHandle&& other) noexcept {
        if (this != &other) {
            reset();
            x_ = other.x_;
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    XHandle(const XHandle&) = delete;
    XHandle& operator=(const XHandle&) = delete;
    ~XHandle() { reset(); }

    XID get() const { return id_; }
    void forget() { id_ = 0; }  // someone else already destroyed it

private:
    void reset() {
        if (id_ != 0) Free(x_, id_);
        id_ = 0;
    }
    ::Display* x_ = nullptr;
    XID id_ = 0;
};
using XWindow = XHandle<XDestroyWindow>;
using XColormap = XHandle<XFreeColormap>;
using XCursor = XHandle<XFreeCursor>;

constexpr glm::ivec2 kDefaultSize{1280, 720};

class WindowDisplay final : public Display {
public:
    void make_current() override { (void)egl_.make_current(); }
    Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() override {
        return egl_.create_worker_context();
    }
    static Result<std::unique_ptr<Display>> create(const DisplayOptions& options);

    BackendKind kind() const override { return BackendKind::Window; }
    glm::ivec2 size() const override { return size_; }
    double refresh_hz() const override { return 60; }
    gpu::FrameTarget frame_target() const override { return {nullptr, size_}; }
    bool poll_events() override;
    Result<void> present() override;
    std::string describe() const override {
        return fmt::format("window: X11 {} {}x{}", XDisplayString(x_.get()), size_.x, size_.y);
    }

private:
    WindowDisplay() = default;
    void handle(const XEvent& event);
    bool wait_until_mapped();

    // Declaration order is destruction order reversed: EGL's surface goes before the window it draws
    // into, and everything before the connection.
    XDisplayPtr x_;
    XColormap colormap_;
    XWindow window_;
    XCursor blank_cursor_;
    EglContext egl_;
    Atom wm_delete_ = 0;
    glm::ivec2 size_{0, 0};
    bool mapped_ = false;
    bool closed_ = false;
};

// An invisible cursor: signage has no pointer, but X shows one over the window unless told otherwise.
XCursor make_blank_cursor(::Display* x, Window window) {
    const char empty[1] = {0};
    const Pixmap pixmap = XCreateBitmapFromData(x, window, empty, 1, 1);
    XColor black{};
    const Cursor cursor = XCreatePixmapCursor(x, pixmap, pixmap, &black, &black, 0, 0);
    XFreePixmap(x, pixmap);  // the cursor keeps its own reference
    return XCursor(x, cursor);
}

// EWMH: a window mapped with _NET_WM_STATE_FULLSCREEN already set starts fullscreen.
void request_fullscreen(::Display* x, Window window) {
    const Atom state = XInternAtom(x, "_NET_WM_STATE", False);
    const Atom fullscreen = XInternAtom(x, "_NET_WM_STATE_FULLSCREEN", False);
    XChangeProperty(x, window, state, XA_ATOM, 32, PropModeReplace,
                    reinterpret_cast<const unsigned char*>(&fullscreen), 1);
}

Result<std::unique_ptr<Display>> WindowDisplay::create(const DisplayOptions& options) {
    const char* display_env = std::getenv("DISPLAY");
    std::unique_ptr<WindowDisplay> d{new WindowDisplay()};
    d->x_.reset(XOpenDisplay(nullptr));
    if (!d->x_)
        return make_error(ExitCode::Display, "window: cannot open X display '{}' (is DISPLAY set?)",
                          display_env ? display_env : "");
    ::Display* x = d->x_.get();
    const int screen = XDefaultScreen(x);
    const Window root = XRootWindow(x, screen);

    auto egl = EglContext::create(
        {.platform = EGL_PLATFORM_X11_KHR, .native_display = x, .window_surface = true, .native_visual = 0});
    if (!egl) return make_error(ExitCode::Display, "window: {}: {}", XDisplayString(x), egl.error().message);
    d->egl_ = std::move(*egl);

    // The window must use the visual of the EGL config, or the surface cannot be made (BadMatch).
    EGLint visual_id = 0;
    eglGetConfigAttrib(d->egl_.display(), d->egl_.config(), EGL_NATIVE_VISUAL_ID, &visual_id);
    XVisualInfo wanted{};
    wanted.visualid = static_cast<VisualID>(visual_id);
    int count = 0;
    const std::unique_ptr<XVisualInfo, FreeX> info{XGetVisualInfo(x, VisualIDMask, &wanted, &count)};
    if (!info || count == 0)
        return make_error(ExitCode::Display, "window: {}: no X visual 0x{:x} for the EGL config",
                          XDisplayString(x), visual_id);

    d->size_ = options.size.x > 0 && options.size.y > 0 ? options.size : kDefaultSize;
    if (options.fullscreen) d->size_ = {XDisplayWidth(x, screen), XDisplayHeight(x, screen)};

    d->colormap_ = XColormap(x, XCreateColormap(x, root, info->visual, AllocNone));
    XSetWindowAttributes attributes{};
    attributes.colormap = d->colormap_.get();
    attributes.background_pixel = 0;
    attributes.border_pixel = 0;
    attributes.event_mask = StructureNotifyMask;
    const Window window = XCreateWindow(
        x, root, 0, 0, static_cast<unsigned>(d->size_.x), static_cast<unsigned>(d->size_.y), 0, info->depth,
        InputOutput, info->visual, CWColormap | CWBackPixel | CWBorderPixel | CWEventMask, &attributes);
    d->window_ = XWindow(x, window);
    XStoreName(x, window, "Puddle");
    d->wm_delete_ = XInternAtom(x, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(x, window, &d->wm_delete_, 1);
    if (options.fullscreen) {
        request_fullscreen(x, window);
        d->blank_cursor_ = make_blank_cursor(x, window);
        XDefineCursor(x, window, d->blank_cursor_.get());
    }
    XMapWindow(x, window);
    // Frames swapped before the window is on screen are lost; wait so the first one is seen.
    if (!d->wait_until_mapped())
        spdlog::warn("window: {}: window not mapped after 2 s, continuing", XDisplayString(x));

    // EGL_EXT_platform_x11 takes a pointer to the Window, not the Window itself.
    Window native = window;
    if (auto attached = d->egl_.attach_window(&native); !attached)
        return make_error(ExitCode::Display, "window: {}: {}", XDisplayString(x), attached.error().message);
    return std::unique_ptr<Display>(std::move(d));
}

bool WindowDisplay::wait_until_mapped() {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::seconds(2);
    ::Display* x = x_.get();
    XFlush(x);
    while (!mapped_ && !closed_) {
        while (!mapped_ && XPending(x) > 0) {
            XEvent event;
            XNextEvent(x, &event);
            handle(event);
        }
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (mapped_ || left <= 0) break;
        pollfd p{XConnectionNumber(x), POLLIN, 0};
        ::poll(&p, 1, static_cast<int>(left));
    }
    return mapped_;
}

void WindowDisplay::handle(const XEvent& event) {
    switch (event.type) {
        case MapNotify:
            mapped_ = true;
            break;
        case UnmapNotify:
            mapped_ = false;
            break;
        case ConfigureNotify:
            size_ = {event.xconfigure.width, event.xconfigure.height};
            break;
        case ClientMessage:
            if (static_cast<Atom>(event.xclient.data.l[0]) == wm_delete_) closed_ = true;
            break;
        case DestroyNotify:
            window_.forget();
            closed_ = true;
            break;
        default:
            break;
    }
}

bool WindowDisplay::poll_events() {
    ::Display* x = x_.get();
    while (XPending(x) > 0) {
        XEvent event;
        XNextEvent(x, &event);
        handle(event);
    }
    return !closed_;
}

Result<void> WindowDisplay::present() {
    if (!egl_.swap_buffers())
        return make_error(ExitCode::Display, "window: {}: eglSwapBuffers: {}", XDisplayString(x_.get()),
                          egl_error_name(eglGetError()));
    return {};
}

}  // namespace

Result<std::unique_ptr<Display>> create_window_display(const DisplayOptions& options) {
    return WindowDisplay::create(options);
}

}  // namespace puddle::platform
