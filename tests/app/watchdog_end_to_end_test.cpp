// The watchdog through a live edit: the real binary under a systemd-like notify socket is pointed, by
// an edit of its config, at a panorama large enough that reading and converting it takes seconds. The
// frames, and so the WATCHDOG=1 pings, must go on meanwhile (the old code held one
// frame for the whole load, 12 to 17 s for an 8192x4096 sky, and systemd would have restarted it).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "assets/image_io.hpp"
#include "support/running_puddle.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"

namespace puddle::test {
namespace {

using Clock = std::chrono::steady_clock;

// A notify socket read as systemd reads it, each message with the time it arrived.
class NotifySocket {
public:
    explicit NotifySocket(std::string path) : path_(std::move(path)) {
        fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
        sockaddr_un addr{};
        addr.sun_family = AF_UNIX;
        std::snprintf(addr.sun_path, sizeof addr.sun_path, "%s", path_.c_str());
        bound_ = ::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
        listener_ = std::thread([this] {
            char msg[512];
            while (!done_) {
                const ssize_t n = ::recv(fd_, msg, sizeof msg, 0);
                if (n <= 0) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                    continue;
                }
                std::lock_guard lock(mutex_);
                got_.push_back({Clock::now(), std::string(msg, static_cast<std::size_t>(n))});
            }
        });
    }
    ~NotifySocket() {
        done_ = true;
        listener_.join();
        ::close(fd_);
    }
    NotifySocket(const NotifySocket&) = delete;
    NotifySocket& operator=(const NotifySocket&) = delete;

    struct Message {
        Clock::time_point at;
        std::string text;
    };
    std::vector<Message> received() const {
        std::lock_guard lock(mutex_);
        return got_;
    }
    int count(const std::string& prefix) const {
        const auto all = received();
        return static_cast<int>(std::count_if(
            all.begin(), all.end(), [&](const Message& m) { return m.text.rfind(prefix, 0) == 0; }));
    }
    // The longest wait for a WATCHDOG=1, in seconds, from the message before it (READY=1 or a ping).
    double longest_ping_gap() const {
        const auto all = received();
        double longest = 0;
        for (std::size_t i = 1; i < all.size(); ++i)
            if (all[i].text == "WATCHDOG=1")
                longest = std::max(longest, std::chrono::duration<double>(all[i].at - all[i - 1].at).count());
        return longest;
    }
    bool ok() const { return bound_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_ = -1;
    bool bound_ = false;
    std::atomic<bool> done_{false};
    mutable std::mutex mutex_;
    std::vector<Message> got_;
    std::thread listener_;
};

// Polls `done` every 100 ms for up to `seconds` (llvmpipe on a busy CI machine is slow).
template <class Done>
bool wait_until(Running& puddle, double seconds, Done&& done) {
    const auto end =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    while (Clock::now() < end) {
        if (done()) return true;
        if (!puddle.running()) return done();
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
}

TEST(WatchdogEndToEnd, ALiveEditToALargeSkyKeepsThePingsWithinHalfTheWatchdogPeriod) {
    TempDir dir;
    // 4096x2048 float, converted to 2048-texel faces: on this kind of machine reading and converting
    // it takes several seconds, more than the 2 s the watchdog below allows between pings. Mostly green,
    // so the new sky shows in the puddle's reflection (the procedural night sky is dark blue).
    const std::string sky = (dir / "large sky.hdr").string();
    {
        assets::Image panorama = assets::Image::make(4096, 2048, assets::PixelFormat::RGBA32F);
        for (int y = 0; y < panorama.height; ++y)
            for (int x = 0; x < panorama.width; ++x) {
                float* p = panorama.pixelf(x, y);
                p[0] = 0.1f, p[1] = 0.6f + 0.2f * static_cast<float>((x / 64 + y / 64) % 2), p[2] = 0.1f,
                p[3] = 1.0f;
            }
        write_float_image(sky, panorama);
    }
    const std::string config = dir.write("puddle.toml", "[rain]\nintensity = 0\n");
    NotifySocket systemd((dir / "notify").string());
    ASSERT_TRUE(systemd.ok());
    constexpr double watchdog_seconds = 4.0;
    const std::string screenshot = (dir / "after.png").string();
    Running puddle({"-b", "headless", "--size", "160x90", "--frames", "0", "--config", config, "--screenshot",
                    screenshot},
                   dir / "log.txt", {"NOTIFY_SOCKET=" + systemd.path(), "WATCHDOG_USEC=4000000"});
    ASSERT_TRUE(wait_until(puddle, 120, [&] { return systemd.count("READY=1") == 1; })) << puddle.log();

    // An editor's save: a new file renamed over the old one.
    std::filesystem::rename(dir.write("puddle.toml.new", "[rain]\nintensity = 0\n[environment]\nimage = \"" +
                                                             sky + "\"\nface_size = 2048\n"),
                            config);
    const std::string shown = "environment: " + sky + " (2048x2048 faces";
    ASSERT_TRUE(wait_until(puddle, 400, [&] { return puddle.log().find(shown) != std::string::npos; }))
        << puddle.log();
    // Frames with the new sky, then the screenshot written at exit.
    const int pings = systemd.count("WATCHDOG=1");
    ASSERT_TRUE(wait_until(puddle, 60, [&] { return systemd.count("WATCHDOG=1") >= pings + 2; }))
        << puddle.log();
    ASSERT_EQ(puddle.stop(), 0) << puddle.log();

    const auto messages = systemd.received();
    ASSERT_GE(messages.size(), 3u);
    EXPECT_EQ(messages.front().text.rfind("READY=1", 0), 0u);
    const double longest = systemd.longest_ping_gap();
    RecordProperty("longest_gap_ms", static_cast<int>(longest * 1000));
    EXPECT_LT(longest, watchdog_seconds / 2) << "the longest gap between pings, in seconds\n" << puddle.log();
    EXPECT_NE(puddle.log().find("environment: loading " + sky +
                                " (showing procedural night sky until it is ready)"),
              std::string::npos)
        << puddle.log();

    auto after = assets::read_image(screenshot);
    ASSERT_TRUE(after.ok()) << after.error().message;
    // The reflection of the green sky: the bottom half of the picture (the puddle) turns green.
    double r = 0, g = 0, b = 0;
    for (int y = after->height / 2; y < after->height; ++y)
        for (int x = 0; x < after->width; ++x) {
            const std::uint8_t* p = after->pixel8(x, y);
            r += p[0], g += p[1], b += p[2];
        }
    EXPECT_GT(g, 1.5 * r) << "mean green " << g << ", red " << r;
    EXPECT_GT(g, 1.5 * b) << "mean green " << g << ", blue " << b;
}

// A slow scene headless: every frame waits for the one before it on the GPU, as a swap chain does, so
// the pings come at the scene's own pace. Before, present() only flushed: llvmpipe queued dozens of
// ocean frames, then one frame blocked for all of them, 5 to 11 s without a ping (a new user's review).
TEST(WatchdogEndToEnd, AHeadlessOceanPingsAtItsOwnPaceInsteadOfQueueingFrames) {
    TempDir dir;
    NotifySocket systemd((dir / "notify").string());
    ASSERT_TRUE(systemd.ok());
    constexpr double watchdog_seconds = 2.0;
    Running puddle({"-b", "headless", "--size", "320x180", "--frames", "0", "--set", "scene.kind=ocean"},
                   dir / "log.txt", {"NOTIFY_SOCKET=" + systemd.path(), "WATCHDOG_USEC=2000000"});
    ASSERT_TRUE(wait_until(puddle, 120, [&] { return systemd.count("READY=1") == 1; })) << puddle.log();
    ASSERT_TRUE(wait_until(puddle, 120, [&] { return systemd.count("WATCHDOG=1") >= 12; })) << puddle.log();
    ASSERT_EQ(puddle.stop(), 0) << puddle.log();
    const double longest = systemd.longest_ping_gap();
    RecordProperty("longest_gap_ms", static_cast<int>(longest * 1000));
    EXPECT_LT(longest, watchdog_seconds / 2) << "the longest gap between pings, in seconds\n" << puddle.log();
}

// The same for the camera ("camera opening"): a live edit switches the reflection to
// a mock camera folder of large images, which takes a second or more to decode. The old code decoded it
// inside one frame; now the worker does, and the pings go on.
TEST(WatchdogEndToEnd, ALiveSwitchToALargeMockCameraKeepsThePingsWithinHalfTheWatchdogPeriod) {
    TempDir dir;
    // 32 noisy 1920x1080 frames, 253 MiB decoded (the mock's limit is 256 MiB): one encoded, the others
    // hard links to it, so writing them is quick and takes one file's space, and reading them is not.
    const auto folder = dir / "camera";
    std::filesystem::create_directory(folder);
    {
        assets::Image frame = assets::Image::make(1920, 1080);
        std::uint32_t noise = 12345;
        for (std::uint8_t& byte : frame.data)
            byte = static_cast<std::uint8_t>((noise = noise * 1664525u + 1013904223u) >> 24);
        ASSERT_TRUE(assets::write_png((folder / "00.png").string(), frame));
        for (int i = 1; i < 32; ++i)
            std::filesystem::create_hard_link(folder / "00.png", folder / fmt::format("{:02}.png", i));
    }
    const std::string config = dir.write("puddle.toml", "[rain]\nintensity = 0\n");
    NotifySocket systemd((dir / "notify").string());
    ASSERT_TRUE(systemd.ok());
    constexpr double watchdog_seconds = 2.0;
    Running puddle({"-b", "headless", "--size", "160x90", "--frames", "0", "--config", config},
                   dir / "log.txt", {"NOTIFY_SOCKET=" + systemd.path(), "WATCHDOG_USEC=2000000"});
    ASSERT_TRUE(wait_until(puddle, 120, [&] { return systemd.count("READY=1") == 1; })) << puddle.log();

    std::filesystem::rename(dir.write("puddle.toml.new",
                                      "[rain]\nintensity = 0\n[environment]\nsource = \"camera\"\n"
                                      "camera_device = \"mock:" +
                                          folder.string() + "\"\n"),
                            config);
    const std::string streaming = "camera: streaming mock:" + folder.string() + ": 32 image(s) of 1920x1080";
    ASSERT_TRUE(wait_until(puddle, 120, [&] { return puddle.log().find(streaming) != std::string::npos; }))
        << puddle.log();
    const int pings = systemd.count("WATCHDOG=1");
    ASSERT_TRUE(wait_until(puddle, 60, [&] { return systemd.count("WATCHDOG=1") >= pings + 2; }))
        << puddle.log();
    ASSERT_EQ(puddle.stop(), 0) << puddle.log();

    const double longest = systemd.longest_ping_gap();
    RecordProperty("longest_gap_ms", static_cast<int>(longest * 1000));
    EXPECT_LT(longest, watchdog_seconds / 2) << "the longest gap between pings, in seconds\n" << puddle.log();
}

}  // namespace
}  // namespace puddle::test
