// The X11 window backend against a private Xvfb server: the window has the requested size and title,
// a presented frame is what X shows (read back with XGetImage from a second connection), resizes are
// tracked, and WM_DELETE_WINDOW ends the run loop. Skipped where Xvfb is not installed.

#include <GLES3/gl3.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "platform/display.hpp"

// Xlib last: its macros (None, Bool, Status) clash with names in the headers above.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

namespace puddle::platform {
namespace {

constexpr const char* kXvfb = "/usr/bin/Xvfb";

// An Xvfb child process; -displayfd makes it pick a free display number and report it once it accepts
// connections, so tests neither guess numbers nor sleep.
class XvfbServer {
public:
    static std::optional<XvfbServer> start(std::string& why) {
        int pipe_fds[2];
        if (::pipe(pipe_fds) != 0) {
            why = "pipe failed";
            return std::nullopt;
        }
        const std::string fd_arg = std::to_string(pipe_fds[1]);
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // a crashing test must not leave the server behind
            ::close(pipe_fds[0]);
            const int null_fd = ::open("/dev/null", O_WRONLY);
            ::dup2(null_fd, STDOUT_FILENO);
            ::dup2(null_fd, STDERR_FILENO);
            ::execl(kXvfb, "Xvfb", "-displayfd", fd_arg.c_str(), "-screen", "0", "640x480x24", "-nolisten",
                    "tcp", static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(pipe_fds[1]);
        if (pid < 0) {
            ::close(pipe_fds[0]);
            why = "fork failed";
            return std::nullopt;
        }
        XvfbServer server(pid);
        std::string number;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (number.empty() || number.back() != '\n') {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            pollfd p{pipe_fds[0], POLLIN, 0};
            char c = 0;
            if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0 ||
                ::read(pipe_fds[0], &c, 1) != 1)
                break;
            number += c;
        }
        ::close(pipe_fds[0]);
        if (number.empty() || number.back() != '\n') {
            why = "Xvfb did not report a display number within 20 s";
            return std::nullopt;
        }
        number.pop_back();
        server.name_ = ":" + number;
        return server;
    }

    XvfbServer(XvfbServer&& other) noexcept
        : pid_(std::exchange(other.pid_, -1)), name_(std::move(other.name_)) {}
    XvfbServer& operator=(XvfbServer&& other) noexcept {
        if (this != &other) {
            stop();
            pid_ = std::exchange(other.pid_, -1);
            name_ = std::move(other.name_);
        }
        return *this;
    }
    ~XvfbServer() { stop(); }

    const std::string& name() const { return name_; }

private:
    explicit XvfbServer(pid_t pid) : pid_(pid) {}
    void stop() {
        if (pid_ <= 0) return;
        ::kill(pid_, SIGTERM);
        ::waitpid(pid_, nullptr, 0);
        pid_ = -1;
    }
    pid_t pid_ = -1;
    std::string name_;
};

struct CloseXDisplay {
    void operator()(::Display* x) const { XCloseDisplay(x); }
};

struct Rgb {
    int r = 0, g = 0, b = 0;
};

int channel(unsigned long pixel, unsigned long mask) {
    const int shift = std::countr_zero(mask);
    return static_cast<int>(((pixel & mask) >> shift) * 255 / (mask >> shift));
}

// Polls `done` for up to two seconds: X and the swap chain work asynchronously.
bool eventually(const std::function<bool()>& done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (std::chrono::steady_clock::now() < deadline) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
}

class WindowDisplayTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!std::filesystem::exists(kXvfb)) GTEST_SKIP() << kXvfb << " not installed (apt install xvfb)";
        std::string why;
        server_ = XvfbServer::start(why);
        ASSERT_TRUE(server_) << why;
        if (const char* old = std::getenv("DISPLAY")) old_display_ = old;
        ::setenv("DISPLAY", server_->name().c_str(), 1);
        observer_.reset(XOpenDisplay(server_->name().c_str()));
        ASSERT_TRUE(observer_) << "cannot connect to " << server_->name();
    }

    void TearDown() override {
        observer_.reset();
        if (old_display_)
            ::setenv("DISPLAY", old_display_->c_str(), 1);
        else
            ::unsetenv("DISPLAY");
    }

    std::unique_ptr<Display> open_window(glm::ivec2 size, bool fullscreen = false) {
        DisplayOptions options;
        options.backend = BackendKind::Window;
        options.size = size;
        options.fullscreen = fullscreen;
        auto display = create_window_display(options);
        if (!display.ok()) ADD_FAILURE() << display.error().message;
        return display.ok() ? std::move(display.value()) : nullptr;
    }

    // Our window, found the way a user would: by its title, through a separate connection.
    Window find_window(const char* title) {
        ::Display* x = observer_.get();
        Window root = 0, parent = 0;
        Window* children = nullptr;
        unsigned count = 0;
        Window found = 0;
        if (!XQueryTree(x, XDefaultRootWindow(x), &root, &parent, &children, &count)) return 0;
        for (unsigned i = 0; i < count && found == 0; ++i) {
            char* name = nullptr;
            if (XFetchName(x, children[i], &name) && name) {
                if (std::string(name) == title) found = children[i];
                XFree(name);
            }
        }
        if (children) XFree(children);
        return found;
    }

    std::optional<Rgb> read_pixel(Window window, int px, int py) {
        XImage* image = XGetImage(observer_.get(), window, px, py, 1, 1, AllPlanes, ZPixmap);
        if (!image) return std::nullopt;
        const unsigned long pixel = XGetPixel(image, 0, 0);
        const Rgb rgb{channel(pixel, image->red_mask), channel(pixel, image->green_mask),
                      channel(pixel, image->blue_mask)};
        XDestroyImage(image);
        return rgb;
    }

    // Clears framebuffer 0 to a colour and presents it; the test's own GL, not the render system's.
    static void clear_and_present(Display& display, float r, float g, float b) {
        glClearColor(r, g, b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const auto presented = display.present();
        ASSERT_TRUE(presented.ok()) << presented.error().message;
    }

    std::optional<XvfbServer> server_;
    std::optional<std::string> old_display_;
    std::unique_ptr<::Display, CloseXDisplay> observer_;
};

bool near(const std::optional<Rgb>& got, Rgb want) {
    return got && std::abs(got->r - want.r) <= 2 && std::abs(got->g - want.g) <= 2 &&
           std::abs(got->b - want.b) <= 2;
}

std::string to_string(const std::optional<Rgb>& c) {
    return c ? "(" + std::to_string(c->r) + ", " + std::to_string(c->g) + ", " + std::to_string(c->b) + ")"
             : "no image";
}

TEST_F(WindowDisplayTest, OpensAWindowOfTheRequestedSize) {
    auto display = open_window({320, 240});
    ASSERT_TRUE(display);
    EXPECT_EQ(display->kind(), BackendKind::Window);
    EXPECT_TRUE(display->shows_frames());
    EXPECT_FALSE(display->switches_output_power()) << "a window draws black instead";
    EXPECT_FALSE(display->owns_the_console());
    EXPECT_EQ(display->size(), glm::ivec2(320, 240));
    EXPECT_EQ(display->frame_target().texture, nullptr);
    EXPECT_EQ(display->frame_target().size, glm::ivec2(320, 240));
    EXPECT_EQ(display->describe(), "window: X11 " + server_->name() + " 320x240");
    EXPECT_TRUE(display->poll_events());

    const Window window = find_window("Puddle");
    ASSERT_NE(window, 0u) << "no top-level window titled Puddle";
    XWindowAttributes attributes{};
    ASSERT_TRUE(XGetWindowAttributes(observer_.get(), window, &attributes));
    EXPECT_EQ(attributes.width, 320);
    EXPECT_EQ(attributes.height, 240);
    EXPECT_EQ(attributes.map_state, IsViewable);
}

TEST_F(WindowDisplayTest, DefaultSizeIs1280x720) {
    auto display = open_window({0, 0});
    ASSERT_TRUE(display);
    EXPECT_EQ(display->size(), glm::ivec2(1280, 720));
}

TEST_F(WindowDisplayTest, PresentShowsTheClearedFrame) {
    auto display = open_window({320, 240});
    ASSERT_TRUE(display);
    const Window window = find_window("Puddle");
    ASSERT_NE(window, 0u);

    // Two frames of different colours, so a stale or never-updated window cannot pass.
    clear_and_present(*display, 0.2f, 0.6f, 0.9f);
    const Rgb first{51, 153, 230};
    std::optional<Rgb> got;
    EXPECT_TRUE(eventually([&] {
        display->poll_events();
        got = read_pixel(window, 160, 120);
        return near(got, first) && near(read_pixel(window, 0, 0), first) &&
               near(read_pixel(window, 319, 239), first);
    })) << "centre pixel "
        << to_string(got) << ", want (51, 153, 230)";

    clear_and_present(*display, 1.0f, 0.0f, 0.0f);
    EXPECT_TRUE(eventually([&] {
        display->poll_events();
        got = read_pixel(window, 160, 120);
        return near(got, {255, 0, 0});
    })) << "centre pixel "
        << to_string(got) << ", want (255, 0, 0)";
}

TEST_F(WindowDisplayTest, TracksResizes) {
    auto display = open_window({320, 240});
    ASSERT_TRUE(display);
    const Window window = find_window("Puddle");
    ASSERT_NE(window, 0u);
    XResizeWindow(observer_.get(), window, 200, 150);
    XSync(observer_.get(), False);
    EXPECT_TRUE(eventually([&] {
        display->poll_events();
        return display->size() == glm::ivec2(200, 150);
    })) << "size "
        << display->size().x << "x" << display->size().y;
    EXPECT_EQ(display->frame_target().size, glm::ivec2(200, 150));
}

TEST_F(WindowDisplayTest, CloseRequestEndsPollEvents) {
    auto display = open_window({320, 240});
    ASSERT_TRUE(display);
    const Window window = find_window("Puddle");
    ASSERT_NE(window, 0u);
    ASSERT_TRUE(display->poll_events());

    // What a window manager sends when the user clicks the close button.
    ::Display* x = observer_.get();
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = window;
    event.xclient.message_type = XInternAtom(x, "WM_PROTOCOLS", False);
    event.xclient.format = 32;
    event.xclient.data.l[0] = static_cast<long>(XInternAtom(x, "WM_DELETE_WINDOW", False));
    event.xclient.data.l[1] = CurrentTime;
    ASSERT_TRUE(XSendEvent(x, window, False, NoEventMask, &event));
    XSync(x, False);
    EXPECT_TRUE(eventually([&] { return !display->poll_events(); }));
}

TEST_F(WindowDisplayTest, FullscreenCoversTheScreenAndAsksTheWindowManager) {
    auto display = open_window({320, 240}, true);
    ASSERT_TRUE(display);
    EXPECT_EQ(display->size(), glm::ivec2(640, 480));  // the Xvfb screen

    const Window window = find_window("Puddle");
    ASSERT_NE(window, 0u);
    ::Display* x = observer_.get();
    Atom type = 0;
    int format = 0;
    unsigned long count = 0, remaining = 0;
    unsigned char* data = nullptr;
    ASSERT_EQ(XGetWindowProperty(x, window, XInternAtom(x, "_NET_WM_STATE", False), 0, 16, False, XA_ATOM,
                                 &type, &format, &count, &remaining, &data),
              Success);
    ASSERT_NE(data, nullptr);
    ASSERT_EQ(count, 1u);
    Atom state = 0;
    std::memcpy(&state, data, sizeof state);
    XFree(data);
    EXPECT_EQ(state, XInternAtom(x, "_NET_WM_STATE_FULLSCREEN", False));
}

// create_display(Auto) on a machine without a KMS card: with an X server it opens a window.
TEST_F(WindowDisplayTest, AutoPicksTheWindowWhenDisplayIsSet) {
    if (std::filesystem::exists("/dev/dri")) GTEST_SKIP() << "this machine has /dev/dri; auto may pick kms";
    DisplayOptions options;
    options.size = {320, 240};
    auto display = create_display(options);
    ASSERT_TRUE(display.ok()) << display.error().message;
    EXPECT_EQ(display.value()->kind(), BackendKind::Window);
}

// DISPLAY names a server that is not there: auto must still start, headless.
TEST(WindowDisplay, AutoFallsBackToHeadlessWhenTheWindowFails) {
    if (std::filesystem::exists("/dev/dri")) GTEST_SKIP() << "this machine has /dev/dri; auto may pick kms";
    std::optional<std::string> old;
    if (const char* d = std::getenv("DISPLAY")) old = d;
    ::setenv("DISPLAY", ":4095", 1);
    DisplayOptions options;
    options.size = {64, 32};
    auto display = create_display(options);
    if (old)
        ::setenv("DISPLAY", old->c_str(), 1);
    else
        ::unsetenv("DISPLAY");
    ASSERT_TRUE(display.ok()) << display.error().message;
    EXPECT_EQ(display.value()->kind(), BackendKind::Headless);
    EXPECT_EQ(display.value()->size(), glm::ivec2(64, 32));
}

TEST(WindowDisplay, WithoutAnXServerFailsWithDisplayExitCode) {
    std::optional<std::string> old;
    if (const char* d = std::getenv("DISPLAY")) old = d;
    ::unsetenv("DISPLAY");
    const auto display = create_window_display(DisplayOptions{});
    if (old) ::setenv("DISPLAY", old->c_str(), 1);
    ASSERT_FALSE(display.ok());
    EXPECT_EQ(display.error().code, ExitCode::Display);
    EXPECT_EQ(display.error().message, "window: cannot open X display '' (is DISPLAY set?)");
}

}  // namespace
}  // namespace puddle::platform
