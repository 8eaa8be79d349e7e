#pragma once
// A display backend: where frames go. One implementation per file (headless_display.cpp,
// kms_display.cpp, window_display.cpp), chosen at start-up by create_display() in backend_select.cpp.
// Each backend owns its EGL context; after creation the context is current on the calling thread.

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <string_view>

#include "gpu/device.hpp"
#include "gpu/frame_target.hpp"
#include "util/result.hpp"

namespace puddle::platform {

// Whether the EGL display of the current context has `name` (false with no current context); defined in
// egl_context.cpp, declared here so that callers need no EGL header.
bool current_display_has_extension(std::string_view name);

enum class BackendKind { Auto, Headless, Kms, Window };
// "auto", "headless", "kms", "window": the spelling --backend takes (backend_select.cpp's table).
std::string_view backend_name(BackendKind k);

struct DisplayOptions {
    BackendKind backend = BackendKind::Auto;
    glm::ivec2 size{0, 0};    // 0x0: the mode's or window's natural size (headless: 640x360)
    bool fullscreen = false;  // window backend: ask the window manager for fullscreen
    std::string card;         // kms: "/dev/dri/card1"; empty = the first card that can modeset
    std::string connector;    // kms: "HDMI-A-1"; empty = the first connected connector
    std::string mode;         // kms: "1920x1080" or "1920x1080@60"; empty = the preferred mode
};

class Display {
public:
    virtual ~Display() = default;
    Display() = default;
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;

    // Called once the Device exists; a backend that renders offscreen makes its target here (an error
    // when the GPU cannot make it, e.g. a --size that does not fit in GPU memory).
    virtual Result<void> prepare(gpu::Device& /*device*/) { return {}; }
    // Makes this display's EGL context current on the calling thread (a process may hold several, as tests
    // do).
    virtual void make_current() = 0;
    virtual BackendKind kind() const = 0;
    // What differs between backends, asked instead of comparing kind():
    // Whether anyone sees the frames (false headless: the run renders a fixed number of frames and
    // writes the last one as a PNG unless told otherwise).
    virtual bool shows_frames() const { return true; }
    // Whether set_power really switches an output off (kms: DPMS); otherwise the caller draws black.
    virtual bool switches_output_power() const { return false; }
    // Whether this display takes over the text console (kms), which must then stop drawing over it.
    virtual bool owns_the_console() const { return false; }
    virtual glm::ivec2 size() const = 0;
    // Frames per second the display shows, the default target of the adaptive scale (render.target_fps
    // -1): kms the mode's refresh, a window 60 (X11 does not say without XRandR), headless 0 (none).
    virtual double refresh_hz() const { return 0; }
    // Where the render system draws this frame: an offscreen texture (headless) or framebuffer 0.
    virtual gpu::FrameTarget frame_target() const = 0;
    // Handles window-system or input events; false once the user asked to close the display.
    virtual bool poll_events() = 0;
    // Shows the frame drawn into frame_target(): swap buffers, or a vblank-paced page flip.
    virtual Result<void> present() = 0;
    // Switches the output off (no signal: the monitor's power saving, a TV's "no input") and on again
    // with the same mode. While off, present() shows nothing and returns at once. kms: the connector's
    // DPMS property (the kernel's atomic helpers turn it into CRTC ACTIVE = 0), and a full modeset on the
    // first frame after; window and headless have no output to switch, so they keep presenting and the
    // caller draws black. Errors name the card, the connector and the call.
    virtual Result<void> set_power(bool on) {
        powered_ = on;
        return {};
    }
    // A context sharing this display's GL objects, for the pipeline compiler's worker thread
    // (gpu/worker_context.hpp); an error when the platform cannot make one (then shaders compile on the
    // frame thread, as they must without one).
    virtual Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() = 0;
    // One line for the start-up log: device, connector, mode, size.
    virtual std::string describe() const = 0;

protected:
    bool powered_ = true;
};

// One factory per backend file.
Result<std::unique_ptr<Display>> create_headless_display(const DisplayOptions& options);
Result<std::unique_ptr<Display>> create_kms_display(const DisplayOptions& options);
Result<std::unique_ptr<Display>> create_window_display(const DisplayOptions& options);

// kms_display.cpp: a /dev/dri/card* that can modeset and that nobody else holds, or why there is none.
struct KmsProbe {
    std::string card;    // empty when none is usable
    std::string reason;  // why it was chosen or why none was
};
KmsProbe probe_kms(const std::string& preferred_card);

// backend_select.cpp: resolves Auto (kms, else window when DISPLAY is set, else headless), logs the
// choice and the reason in one line, and builds the backend.
Result<std::unique_ptr<Display>> create_display(const DisplayOptions& options);

}  // namespace puddle::platform
