// The camera feed inside the running engine, against the fake V4L2 device: no device at start, a
// device that appears, vanishes mid-stream and comes back, one whose open or close blocks. The display
// never stops, the puddle reflects the cubemap while no camera streams, and nothing leaks.
#include "systems/sky/camera_system.hpp"

#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "assets/image_io.hpp"
#include "camera/fake_v4l2_device.hpp"
#include "support/gpu_fixture.hpp"
#include "support/image_bomb.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr const char* fake_path = "/dev/puddle-test-camera";  // never a real device

// Whether `done` holds within `seconds` of wall-clock time (the camera worker runs beside the test).
template <class Done>
bool wait_for(Done done, double seconds = 10.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

struct Rig {
    FakeV4l2Device dev;  // outlives the engine, whose feed closes through it
    std::unique_ptr<app::Engine> engine;
    ~Rig() { dev.release(); }  // a held call must not keep the engine's worker from being joined
    systems::CameraFeed& feed() { return engine->world().resource<systems::CameraFeed>(); }
    const systems::CameraEnvironment& env() { return engine->world().resource<systems::CameraEnvironment>(); }
    // One frame, after the camera worker has finished what the last frame gave it (bounded), so a frame
    // count measures the feed as a synchronous open would have.
    void frame() {
        EXPECT_TRUE(wait_for([&] { return !feed().worker.running(); })) << "the camera worker is stuck";
        step();
    }
    // One frame, whatever the worker is doing; while streaming, the camera delivers a white YUYV frame
    // each display frame.
    void step() {
        if (dev.streaming()) {
            std::vector<std::byte> f(static_cast<std::size_t>(dev.size_image()), std::byte{128});
            for (std::size_t i = 0; i < f.size(); i += 2) f[i] = std::byte{235};
            dev.push_frame({f});
        }
        auto r = engine->frame(1.0 / 30.0);
        ASSERT_TRUE(r) << r.error().message;
    }
    // Frames until `done` holds; returns the seconds it took, or -1 after `limit` seconds.
    template <class Done>
    double until(Done done, double limit) {
        for (int n = 0; n * (1.0 / 30.0) <= limit; ++n) {
            if (done()) return n / 30.0;
            frame();
        }
        return -1.0;
    }
    // Frames (stepped, not waiting for the worker) until a call waits in the device's hold, once the
    // device has been opened; false if none does within `limit` seconds of frames. A frame that makes the
    // held call on its own thread returns only when the hold gives up, and the call is then no longer
    // waiting.
    bool step_until_held(double limit) {
        for (int n = 0; n * (1.0 / 30.0) <= limit; ++n) {
            step();
            if (dev.opens() > 0 && wait_for([&] { return dev.held_calls() > 0; }, 0.2)) return true;
        }
        return false;
    }
};

std::unique_ptr<app::Engine> engine_on_the_fake(const char* width = "64", const char* height = "36") {
    return make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     std::string("environment.camera_width=") + width,
                     std::string("environment.camera_height=") + height}),
        {96, 54});
}

TEST(CameraFeed, FallsBackToTheCubemapAndRecoversByItself) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.dev.max_buffers = 3;
    rig.dev.unplug();
    rig.engine = make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     "environment.camera_width=64", "environment.camera_height=36"}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;

    // No device at start: the cubemap, and the display keeps going.
    for (int i = 0; i < 10; ++i) rig.frame();
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_EQ(rig.env().reflection(), nullptr);
    const assets::Image cubemap = rig.engine->read_frame();

    // Plugged in: found by the retry timer within a second, and the reflection changes.
    rig.dev.replug();
    const double found = rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5);
    EXPECT_GE(found, 0.0) << "streaming did not start within 1.5 s";
    EXPECT_LE(found, 1.0 + 2.0 / 30.0);
    for (int i = 0; i < 3; ++i) rig.frame();
    const assets::Image camera = rig.engine->read_frame();
    EXPECT_GT(mean_luma(camera), mean_luma(cubemap) + 20)
        << "a white room reflects brighter than the night sky";
    EXPECT_EQ(rig.dev.live_mappings(), 3);

    // Unplugged mid-stream: back to the cubemap at the next frame, every mapping and descriptor released.
    rig.dev.unplug();
    rig.frame();
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_EQ(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.dev.live_mappings(), 0);
    EXPECT_EQ(rig.dev.open_fds(), 0);
    EXPECT_EQ(rig.feed().losses, 1u);
    for (int i = 0; i < 40; ++i) rig.frame();  // retries fail quietly while it is away
    EXPECT_EQ(rig.dev.open_fds(), 0);

    // Plugged back: it resumes by itself.
    rig.dev.replug();
    const double resumed = rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5);
    EXPECT_GE(resumed, 0.0) << "streaming did not resume within 1.5 s";
    EXPECT_EQ(rig.dev.opens(), 2);
}

// Review 15, finding 6: a live mock folder that failed was read again every second, for ever. Now it is
// tried again only once its files change, and then it streams.
TEST(CameraFeed, AFailedMockFolderIsTriedAgainOnlyWhenItsFilesChange) {
    TempDir dir;
    const auto folder = dir / "camera";
    std::filesystem::create_directory(folder);
    ASSERT_TRUE(assets::write_png((folder / "0.png").string(), assets::Image::make(8, 4)));
    std::ofstream(folder / "a.png", std::ios::binary) << png_claiming(16000, 16000);  // does not match
    Rig rig;
    rig.engine = make_engine(
        make_params({"environment.source=cubemap", "environment.camera_device=mock:" + folder.string()}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.engine->params().set(params::ParamId::environment_source, std::string("camera"),
                             params::ParamSource::CommandLine);
    for (int i = 0; i < 100; ++i) rig.frame();  // 3.3 s: three retries were due
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_NE(rig.feed().last_failure.find("all must match"), std::string::npos) << rig.feed().last_failure;
    EXPECT_EQ(rig.feed().open_attempts, 1u) << "the unchanged folder is not read again";

    ASSERT_TRUE(assets::write_png((folder / "a.png").string(), assets::Image::make(8, 4)));  // fixed
    const double found = rig.until([&] { return rig.feed().streaming(); }, 1.5);
    EXPECT_GE(found, 0.0) << "the fixed folder did not stream within 1.5 s";
    EXPECT_EQ(rig.feed().open_attempts, 2u);
}

TEST(CameraFeed, SourceCubemapClosesTheDeviceAndChangedSettingsReopenIt) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}, {32, 18}}}};
    rig.engine = make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     "environment.camera_width=64", "environment.camera_height=36"}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5), 0.0);
    EXPECT_EQ(rig.dev.negotiated_width(), 64);

    // Live tuning: a new size reopens the device at once.
    rig.engine->params().set(params::ParamId::environment_camera_width, 32, params::ParamSource::CommandLine);
    rig.engine->params().set(params::ParamId::environment_camera_height, 18,
                             params::ParamSource::CommandLine);
    ASSERT_GE(
        rig.until([&] { return rig.env().reflection() != nullptr && rig.dev.negotiated_width() == 32; }, 0.5),
        0.0);
    EXPECT_EQ(rig.dev.opens(), 2);
    EXPECT_EQ(rig.dev.open_fds(), 1);

    rig.engine->params().set(params::ParamId::environment_source, std::string("cubemap"),
                             params::ParamSource::CommandLine);
    rig.frame();
    EXPECT_EQ(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.dev.open_fds(), 0);
    EXPECT_EQ(rig.dev.live_mappings(), 0);
}

TEST(CameraFeed, NewestFrameWinsAndASlowCameraNeverStallsTheDisplay) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.dev.max_buffers = 4;
    rig.engine = make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     "environment.camera_width=64", "environment.camera_height=36"}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5), 0.0);
    auto frame_of = [&](std::uint8_t luma) {
        std::vector<std::byte> f(static_cast<std::size_t>(rig.dev.size_image()), std::byte{128});
        for (std::size_t i = 0; i < f.size(); i += 2) f[i] = std::byte{luma};
        return FakeFrame{f};
    };
    auto centre_luma = [&] { return mean_luma(rig.engine->read_frame(), 30, 20, 66, 34); };
    // Three frames arrive within one display frame: one upload, the newest (bright) one.
    const std::uint64_t before = rig.feed().frames;
    for (std::uint8_t luma : {16, 16, 235}) rig.dev.push_frame(frame_of(luma));
    ASSERT_TRUE(rig.engine->frame(1.0 / 30.0));
    EXPECT_EQ(rig.feed().frames, before + 1);
    const double bright = centre_luma();
    // No frame for a while: the display goes on, keeping the last picture.
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(rig.engine->frame(1.0 / 30.0));
    EXPECT_EQ(rig.feed().frames, before + 1);
    EXPECT_NE(rig.env().reflection(), nullptr);
    EXPECT_NEAR(centre_luma(), bright, 12.0) << "the last frame stays (only the rain moves)";
    // A dark frame then shows at once.
    rig.dev.push_frame(frame_of(16));
    ASSERT_TRUE(rig.engine->frame(1.0 / 30.0));
    EXPECT_LT(centre_luma(), bright - 20);
}

TEST(CameraFeed, ATransientErrorKeepsStreamingAndOnlyARunReopens) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.dev.max_buffers = 3;
    rig.engine = make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     "environment.camera_width=64", "environment.camera_height=36"}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5), 0.0);

    // One EIO from VIDIOC_DQBUF: counted, no reopen, the camera stays in the reflection.
    rig.dev.fail_dqbuf(EIO);
    for (int i = 0; i < 5; ++i) rig.frame();
    EXPECT_EQ(rig.dev.opens(), 1);
    EXPECT_EQ(rig.feed().losses, 0u);
    EXPECT_TRUE(rig.feed().streaming());
    EXPECT_NE(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.feed().faults().errors, 1u);

    // A run of them: the device is closed and reopened, as after an unplug.
    rig.dev.fail_dqbuf(EIO, camera::reopen_after_errors);
    for (int i = 0; i < camera::reopen_after_errors; ++i) rig.frame();
    EXPECT_EQ(rig.feed().losses, 1u);
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_EQ(rig.feed().faults().errors, 1u + camera::reopen_after_errors)
        << "the closed source's count is kept";
    EXPECT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5), 0.0);
    EXPECT_EQ(rig.dev.opens(), 2);
}

TEST(CameraFeed, ACorruptMjpegFrameKeepsThePreviousReflection) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_MJPEG, {{64, 48}}}};
    rig.dev.max_buffers = 3;
    rig.engine = make_engine(
        make_params({"environment.source=camera", std::string("environment.camera_device=") + fake_path,
                     "environment.camera_width=64", "environment.camera_height=48"}),
        {96, 54});
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    auto frame = [&] {
        ASSERT_TRUE(wait_for([&] { return !rig.feed().worker.running(); }));
        ASSERT_TRUE(rig.engine->frame(1.0 / 30.0));
    };
    for (int i = 0; i < 40 && !rig.feed().streaming(); ++i) frame();
    ASSERT_TRUE(rig.feed().streaming());
    rig.dev.push_frame({encode_jpeg(64, 48, 230, 200, 60)});
    frame();
    ASSERT_NE(rig.env().reflection(), nullptr);
    const std::vector<float> shown = rig.engine->device().read_texture(rig.env().colour);

    // A dark frame cut short in its pixel data: libjpeg would fill the rest with grey; it is dropped.
    const auto dark = encode_jpeg(64, 48, 20, 30, 40);
    rig.dev.push_frame({cut_in_scan(dark)});
    frame();
    EXPECT_EQ(rig.engine->device().read_texture(rig.env().colour), shown)
        << "the reflection keeps the last whole frame";
    EXPECT_NE(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.feed().faults().dropped, 1u);
    EXPECT_EQ(rig.feed().losses, 0u);
    // The next whole frame shows.
    rig.dev.push_frame({dark});
    frame();
    EXPECT_NE(rig.engine->device().read_texture(rig.env().colour), shown);
}

// Issue 15, fault 6: a UVC camera's VIDIOC_STREAMON can block for seconds. The open waits on the
// worker; every frame meanwhile returns and reflects the cubemap; the camera streams once it returns.
TEST(CameraFeed, AnOpenThatBlocksNeverHoldsUpTheFrames) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.dev.max_buffers = 3;
    rig.dev.hold(VIDIOC_STREAMON);
    rig.engine = engine_on_the_fake();
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    const assets::Image cubemap = rig.engine->read_frame();

    // The retry timer starts the open within a second; it then waits in VIDIOC_STREAMON.
    ASSERT_TRUE(rig.step_until_held(1.5)) << "the open did not wait off the frame thread";
    int frames_while_held = 0;
    for (int i = 0; i < 20; ++i) {
        rig.step();
        if (rig.dev.held_calls() == 1) ++frames_while_held;
    }
    EXPECT_EQ(frames_while_held, 20);
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_EQ(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.dev.opens(), 1) << "no second open while the first is in flight";

    // Released: the camera streams, and the puddle reflects its white room.
    rig.dev.release();
    EXPECT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 0.5), 0.0);
    for (int i = 0; i < 3; ++i) rig.frame();
    EXPECT_TRUE(rig.feed().streaming());
    EXPECT_GT(rig.feed().frames, 0u);
    EXPECT_GT(mean_luma(rig.engine->read_frame()), mean_luma(cubemap) + 20);
    EXPECT_EQ(rig.dev.opens(), 1);
    EXPECT_EQ(rig.dev.live_mappings(), 3);
}

// New settings while the open for the old ones waits: the old source is closed unpolled and the
// one left streaming has the new size.
TEST(CameraFeed, SettingsChangedWhileAnOpenWaitsEndWithTheNewSettings) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}, {32, 18}}}};
    rig.dev.max_buffers = 3;
    rig.dev.hold(VIDIOC_S_FMT);
    rig.engine = engine_on_the_fake();
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_TRUE(rig.step_until_held(1.5)) << "the open did not wait off the frame thread";

    rig.engine->params().set(params::ParamId::environment_camera_width, 32, params::ParamSource::CommandLine);
    rig.engine->params().set(params::ParamId::environment_camera_height, 18,
                             params::ParamSource::CommandLine);
    for (int i = 0; i < 5; ++i) rig.step();
    EXPECT_EQ(rig.dev.held_calls(), 1);
    rig.dev.release();

    ASSERT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 0.5), 0.0);
    EXPECT_EQ(rig.feed().request.width, 32);
    EXPECT_EQ(rig.feed().request.height, 18);
    EXPECT_EQ(rig.dev.negotiated_width(), 32);
    EXPECT_EQ(rig.dev.negotiated_height(), 18);
    EXPECT_EQ(rig.dev.opens(), 2) << "opened for 64x36, closed, reopened for 32x18";
    EXPECT_EQ(rig.dev.open_fds(), 1);
    EXPECT_EQ(rig.dev.live_mappings(), 3);
}

// source = cubemap while the open waits: the source it returns is closed, never streamed.
TEST(CameraFeed, SourceCubemapWhileAnOpenWaitsClosesWhatItOpens) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.dev.hold(VIDIOC_STREAMON);
    rig.engine = engine_on_the_fake();
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_TRUE(rig.step_until_held(1.5)) << "the open did not wait off the frame thread";
    rig.engine->params().set(params::ParamId::environment_source, std::string("cubemap"),
                             params::ParamSource::CommandLine);
    rig.step();
    rig.dev.release();
    for (int i = 0; i < 3; ++i) rig.frame();
    EXPECT_FALSE(rig.feed().streaming());
    EXPECT_EQ(rig.env().reflection(), nullptr);
    EXPECT_EQ(rig.dev.open_fds(), 0);
    EXPECT_EQ(rig.dev.live_mappings(), 0);
    EXPECT_EQ(rig.feed().frames, 0u);
}

// Closing blocks too (VIDIOC_STREAMOFF on a wedged camera): it waits on the worker, not in a frame.
TEST(CameraFeed, ACloseThatBlocksNeverHoldsUpTheFrames) {
    Rig rig;
    rig.dev.path = fake_path;
    rig.dev.formats = {{V4L2_PIX_FMT_YUYV, {{64, 36}}}};
    rig.engine = engine_on_the_fake();
    ASSERT_TRUE(rig.engine);
    rig.feed().io = &rig.dev;
    ASSERT_GE(rig.until([&] { return rig.env().reflection() != nullptr; }, 1.5), 0.0);

    rig.dev.hold(VIDIOC_STREAMOFF);
    rig.engine->params().set(params::ParamId::environment_source, std::string("cubemap"),
                             params::ParamSource::CommandLine);
    ASSERT_TRUE(rig.step_until_held(0.5)) << "the close did not wait off the frame thread";
    int frames_while_held = 0;
    for (int i = 0; i < 10; ++i) {
        rig.step();
        if (rig.dev.held_calls() == 1) ++frames_while_held;
    }
    EXPECT_EQ(frames_while_held, 10);
    EXPECT_EQ(rig.env().reflection(), nullptr);
    rig.dev.release();
    rig.frame();
    EXPECT_EQ(rig.dev.open_fds(), 0);
    EXPECT_EQ(rig.dev.live_mappings(), 0);
}

}  // namespace
}  // namespace puddle::test
