// The production capture code against the fake device: negotiation, buffers, pacing, faults, leaks.
#include "camera/v4l2_capture.hpp"

#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include "camera/camera_source.hpp"
#include "camera/fake_v4l2_device.hpp"

namespace puddle::test {
namespace {

using camera::CaptureRequest;
using camera::FormatPreference;
using camera::V4l2Capture;

bool has_text(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// A YUYV frame whose every Y byte is `luma` and whose padding bytes are 0xEE (never read as pixels).
std::vector<std::byte> yuyv_frame(const FakeV4l2Device& dev, std::uint8_t luma) {
    std::vector<std::byte> f(static_cast<std::size_t>(dev.size_image()), std::byte{0xEE});
    for (int y = 0; y < dev.negotiated_height(); ++y)
        for (int x = 0; x < dev.negotiated_width() * 2; ++x)
            f[std::size_t(y) * dev.bytes_per_line() + x] = std::byte{x % 2 == 0 ? luma : std::uint8_t{128}};
    return f;
}

FakeV4l2Device yuyv_device() {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_MJPEG, {{1920, 1080}}},
                   {V4L2_PIX_FMT_YUYV, {{640, 480}, {320, 180}, {160, 120}}}};
    return dev;
}

TEST(V4l2Capture, TakesTheSizeAndStrideTheDriverWritesBack) {
    FakeV4l2Device dev = yuyv_device();
    auto c = V4l2Capture::open(dev, {.device = "/dev/video0", .width = 300, .height = 200});
    ASSERT_TRUE(c) << c.error().message;
    EXPECT_EQ(c->fourcc(), V4L2_PIX_FMT_YUYV) << "auto prefers an uncompressed format the device has";
    EXPECT_EQ(c->format().width, 320);
    EXPECT_EQ(c->format().height, 180);
    EXPECT_EQ(c->format().stride, 320 * 2 + 64) << "bytesperline as the driver padded it";
    EXPECT_EQ(c->format().layout, camera::PixelLayout::Yuyv);
    EXPECT_EQ(c->format().matrix, camera::YuvMatrix::Bt709) << "REC709 colorspace maps to the BT.709 matrix";
    EXPECT_FALSE(c->format().full_range) << "default quantization of YUV is limited range";
    EXPECT_GT(dev.eintr_count(), 0) << "the fake interrupted some ioctls; they were retried";
}

TEST(V4l2Capture, WorksWithFewerBuffersThanAsked) {
    FakeV4l2Device dev = yuyv_device();
    dev.max_buffers = 2;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180, .buffers = 6});
    ASSERT_TRUE(c) << c.error().message;
    EXPECT_EQ(c->buffer_count(), 2u);
    EXPECT_EQ(dev.live_mappings(), 2);
    EXPECT_EQ(dev.queued_buffers(), 2);
    EXPECT_TRUE(dev.streaming());
    for (int i = 0; i < 5; ++i) {  // more frames than buffers: each is returned in turn
        dev.push_frame({yuyv_frame(dev, static_cast<std::uint8_t>(20 + i))});
        auto f = c->poll();
        ASSERT_TRUE(f) << f.error().message;
        ASSERT_TRUE(f->has_value()) << "frame " << i;
        EXPECT_EQ(std::to_integer<int>((*f)->bytes[0]), 20 + i);
    }
}

TEST(V4l2Capture, OneBufferIsNotEnough) {
    FakeV4l2Device dev = yuyv_device();
    dev.max_buffers = 1;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_FALSE(c);
    EXPECT_TRUE(has_text(c.error().message, "granted 1 buffer(s), need 2")) << c.error().message;
    EXPECT_EQ(dev.open_fds(), 0);
    EXPECT_EQ(dev.live_mappings(), 0);
}

TEST(V4l2Capture, NothingReadyIsNoFrameNotAnError) {
    FakeV4l2Device dev = yuyv_device();
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    for (int i = 0; i < 3; ++i) {
        auto f = c->poll();
        ASSERT_TRUE(f) << f.error().message;
        EXPECT_FALSE(f->has_value());
    }
}

TEST(V4l2Capture, TheNewestFrameWinsAndTheOthersGoBack) {
    FakeV4l2Device dev = yuyv_device();
    dev.max_buffers = 4;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    for (std::uint8_t luma : {50, 60, 70}) dev.push_frame({yuyv_frame(dev, luma)});
    auto f = c->poll();
    ASSERT_TRUE(f && f->has_value());
    EXPECT_EQ(std::to_integer<int>((*f)->bytes[0]), 70);
    EXPECT_EQ((*f)->bytes.size(), static_cast<std::size_t>(dev.size_image())) << "bytesused";
    EXPECT_EQ(dev.queued_buffers(), 3) << "the two older frames were requeued at once; one is held";
    auto g = c->poll();
    ASSERT_TRUE(g);
    EXPECT_FALSE(g->has_value());
    EXPECT_EQ(dev.queued_buffers(), 4) << "the held buffer goes back on the next poll";
}

TEST(V4l2Capture, ZeroCopyKeepsThePreviousFrameFromTheDriver) {
    FakeV4l2Device dev = yuyv_device();
    dev.exports_dmabuf = true;
    dev.max_buffers = 4;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180, .export_dmabuf = true});
    ASSERT_TRUE(c) << c.error().message;
    dev.push_frame({yuyv_frame(dev, 10)});
    ASSERT_TRUE(c->poll());
    EXPECT_EQ(dev.queued_buffers(), 3);
    dev.push_frame({yuyv_frame(dev, 20)});
    auto f = c->poll();
    ASSERT_TRUE(f && f->has_value());
    EXPECT_EQ(dev.queued_buffers(), 2) << "the last frame and the one the GPU may still read";
    ASSERT_TRUE(c->poll());
    EXPECT_EQ(dev.queued_buffers(), 3) << "a frame later the older one goes back";
    dev.push_frame({yuyv_frame(dev, 30)});
    auto g = c->poll();
    ASSERT_TRUE(g && g->has_value());
    EXPECT_EQ(std::to_integer<int>((*g)->bytes[0]), 30);
    EXPECT_EQ(dev.queued_buffers(), 2);
}

TEST(V4l2Capture, DropsErrorFlaggedAndShortBuffers) {
    FakeV4l2Device dev = yuyv_device();
    dev.max_buffers = 4;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    dev.push_frame({yuyv_frame(dev, 90)});
    dev.push_frame({yuyv_frame(dev, 99), true});  // flagged: must not win although it is newest
    auto f = c->poll();
    ASSERT_TRUE(f && f->has_value());
    EXPECT_EQ(std::to_integer<int>((*f)->bytes[0]), 90);
    std::vector<std::byte> shorter = yuyv_frame(dev, 77);
    shorter.resize(shorter.size() / 2);
    dev.push_frame({shorter});
    auto g = c->poll();
    ASSERT_TRUE(g);
    EXPECT_FALSE(g->has_value()) << "half a YUYV frame is dropped";
    EXPECT_EQ(c->dropped(), 2u);
    EXPECT_EQ(dev.queued_buffers(), 4) << "dropped buffers were requeued";
}

TEST(V4l2Capture, VanishingDeviceIsAnErrorAndLeavesNothingBehind) {
    FakeV4l2Device dev = yuyv_device();
    dev.exports_dmabuf = true;
    {
        auto c = V4l2Capture::open(dev, {.width = 320, .height = 180, .export_dmabuf = true});
        ASSERT_TRUE(c) << c.error().message;
        EXPECT_EQ(dev.open_fds(), 3) << "the device and two exported dmabufs";
        dev.push_frame({yuyv_frame(dev, 40)});
        auto f = c->poll();
        ASSERT_TRUE(f && f->has_value());
        EXPECT_GE((*f)->dmabuf_fd, 0);
        dev.unplug();
        auto g = c->poll();
        ASSERT_FALSE(g);
        EXPECT_TRUE(has_text(g.error().message, "/dev/video0")) << g.error().message;
        EXPECT_EQ(dev.live_mappings(), 2) << "still mapped until the capture is dropped";
    }
    EXPECT_EQ(dev.live_mappings(), 0);
    EXPECT_EQ(dev.open_fds(), 0);
}

TEST(V4l2Capture, EnodevFromDqbufIsAnError) {
    FakeV4l2Device dev = yuyv_device();
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    dev.push_frame({yuyv_frame(dev, 40)});
    dev.dqbuf_errno = ENODEV;  // poll says a frame is ready; the device is gone by the time it is dequeued
    auto r = c->poll();
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().message, "camera: /dev/video0: VIDIOC_DQBUF: No such device");
}

TEST(V4l2Capture, UnsupportedFormatListsWhatTheDeviceOffers) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_H264, {{1920, 1080}, {1280, 720}}}, {V4L2_PIX_FMT_YUYV, {{640, 480}}}};
    auto c = V4l2Capture::open(dev, {.format = FormatPreference::Nv12});
    ASSERT_FALSE(c);
    EXPECT_TRUE(has_text(c.error().message, "camera: /dev/video0: ")) << c.error().message;
    EXPECT_TRUE(has_text(c.error().message, "NV12 was asked for")) << c.error().message;
    EXPECT_TRUE(has_text(c.error().message, "H264 1920x1080, 1280x720; YUYV 640x480")) << c.error().message;
    EXPECT_EQ(dev.open_fds(), 0);
}

TEST(V4l2Capture, MissingDeviceNamesThePath) {
    FakeV4l2Device dev = yuyv_device();
    dev.unplug();
    auto c = V4l2Capture::open(dev, {.device = "/dev/video0"});
    ASSERT_FALSE(c);
    EXPECT_EQ(c.error().message, "camera: /dev/video0: open: No such file or directory");
}

TEST(V4l2Source, DecodesMjpegFramesOfVaryingLength) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_MJPEG, {{64, 48}}}};
    dev.max_buffers = 3;
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    const auto a = encode_jpeg(64, 48, 200, 40, 30, 95), b = encode_jpeg(64, 48, 30, 60, 220, 40);
    ASSERT_NE(a.size(), b.size());
    for (const auto& [jpeg, r, g, bl] : {std::tuple{a, 200, 40, 30}, std::tuple{b, 30, 60, 220}}) {
        dev.push_frame({jpeg});
        auto f = (*src)->poll(0.0);
        ASSERT_TRUE(f) << f.error().message;
        ASSERT_TRUE(f->has_value());
        const camera::CameraImage& img = **f;
        EXPECT_EQ(img.layout, camera::PixelLayout::Rgba);
        EXPECT_EQ(img.width, 64);
        EXPECT_EQ(img.stride, 64 * 4);
        const auto* px =
            reinterpret_cast<const std::uint8_t*>(img.data.data()) + (10 * 64 + 20) * 4;  // top half: solid
        EXPECT_NEAR(px[0], r, 6);
        EXPECT_NEAR(px[1], g, 6);
        EXPECT_NEAR(px[2], bl, 6);
    }
    // A truncated JPEG is skipped, not fatal, and the stream goes on.
    std::vector<std::byte> cut(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(a.size() / 3));
    cut[2] = std::byte{0};  // and a broken marker, so libjpeg gives up
    dev.push_frame({cut});
    auto bad = (*src)->poll(0.0);
    ASSERT_TRUE(bad) << "a bad frame does not end the stream";
    EXPECT_FALSE(bad->has_value());
    dev.push_frame({a});
    auto good = (*src)->poll(0.0);
    ASSERT_TRUE(good && good->has_value());
}

}  // namespace
}  // namespace puddle::test
