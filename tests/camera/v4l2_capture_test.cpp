// The production capture code against the fake device: negotiation, buffers, pacing, faults, leaks. The
// CameraSource over it (MJPEG decoding, counters) is tested in v4l2_source_test.cpp.
#include "camera/v4l2_capture.hpp"

#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <cstring>

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
    dev.fail_dqbuf(ENODEV, -1);  // poll says a frame is ready; the device is gone by the time it is dequeued
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

TEST(V4l2Capture, OddSizedNv12FramesMustHoldTheRoundedUpChroma) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_NV12, {{65, 49}}}};
    dev.row_padding = 14;  // bytesperline 80
    dev.max_buffers = 3;
    auto c = V4l2Capture::open(dev, {.width = 65, .height = 49});
    ASSERT_TRUE(c) << c.error().message;
    ASSERT_EQ(c->format().stride, 80);
    // stride * height * 3 / 2 misses the last chroma row of an odd height: 25 rows, not 24.5.
    dev.push_frame({std::vector<std::byte>(80 * 49 * 3 / 2, std::byte{128})});
    auto f = c->poll();
    ASSERT_TRUE(f) << f.error().message;
    EXPECT_FALSE(f->has_value()) << "a frame too short for its format is dropped";
    EXPECT_EQ(c->dropped(), 1u);
    EXPECT_EQ(c->last_drop_reason(), "5880 bytes; NV12 65x49 needs 5906");
    dev.push_frame({std::vector<std::byte>(static_cast<std::size_t>(dev.size_image()), std::byte{128})});
    auto g = c->poll();
    ASSERT_TRUE(g && g->has_value());
    EXPECT_EQ((*g)->bytes.size(), 80u * (49 + 25));
}

TEST(V4l2Capture, ABytesperlineTooShortForTheChromaIsRefusedAtOpen) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_NV12, {{65, 48}}}};
    dev.row_padding = -1;  // bytesperline 65: an odd-width chroma row needs 66
    auto c = V4l2Capture::open(dev, {.width = 65, .height = 48});
    ASSERT_FALSE(c);
    EXPECT_EQ(
        c.error().message,
        "camera: /dev/video0: VIDIOC_S_FMT gave NV12 65x48: bytesperline 65 is shorter than the 66 bytes "
        "of a chroma row");
    EXPECT_EQ(dev.open_fds(), 0);
}

TEST(V4l2Capture, OnlyAVanishedDeviceEndsTheStreamAtOnce) {
    // Errors a device survives (a USB hiccup, a full queue, memory pressure): counted, retried.
    for (int err : {EIO, EPIPE, ENOMEM}) {
        FakeV4l2Device dev = yuyv_device();
        auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
        ASSERT_TRUE(c);
        dev.push_frame({yuyv_frame(dev, 40)});
        dev.fail_dqbuf(err);
        auto f = c->poll();
        ASSERT_TRUE(f) << f.error().message;
        EXPECT_FALSE(f->has_value());
        EXPECT_EQ(c->errors(), 1u);
        EXPECT_EQ(c->last_error(), std::string("VIDIOC_DQBUF: ") + std::strerror(err));
        auto g = c->poll();
        ASSERT_TRUE(g && g->has_value()) << "the frame is dequeued on the next poll";
        EXPECT_EQ(std::to_integer<int>((*g)->bytes[0]), 40);
    }
    // A device that is gone: an error at once, for the caller to close and reopen.
    for (int err : {ENODEV, ENXIO}) {
        FakeV4l2Device dev = yuyv_device();
        auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
        ASSERT_TRUE(c);
        dev.push_frame({yuyv_frame(dev, 40)});
        dev.fail_dqbuf(err);
        auto f = c->poll();
        ASSERT_FALSE(f);
        EXPECT_EQ(f.error().message, std::string("camera: /dev/video0: VIDIOC_DQBUF: ") + std::strerror(err));
    }
    FakeV4l2Device dev = yuyv_device();
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    dev.poll_reports(POLLHUP);
    auto f = c->poll();
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().message, "camera: /dev/video0: the device went away (poll: POLLHUP)");
}

TEST(V4l2Capture, ARunOfErrorsIsAnErrorAndAFrameBetweenResetsIt) {
    FakeV4l2Device dev = yuyv_device();
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    dev.push_frame({yuyv_frame(dev, 40)});
    dev.fail_dqbuf(EIO, camera::reopen_after_errors - 1);
    for (int i = 0; i < camera::reopen_after_errors - 1; ++i) {
        auto f = c->poll();
        ASSERT_TRUE(f) << "failure " << i + 1 << ": " << f.error().message;
        EXPECT_FALSE(f->has_value());
    }
    auto f = c->poll();
    ASSERT_TRUE(f && f->has_value()) << "a frame after the errors";
    dev.fail_dqbuf(EIO, -1);
    for (int i = 0; i < camera::reopen_after_errors - 1; ++i) {
        dev.push_frame({yuyv_frame(dev, 50)});
        ASSERT_TRUE(c->poll()) << "the count started again after the frame; failure " << i + 1;
    }
    dev.push_frame({yuyv_frame(dev, 50)});
    auto g = c->poll();
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().message,
              "camera: /dev/video0: VIDIOC_DQBUF: Input/output error (10 failed calls in a row)");
    EXPECT_EQ(c->errors(), 2u * camera::reopen_after_errors - 1);
}

TEST(V4l2Capture, ABufferWhoseQbufFailsIsGivenBackLater) {
    FakeV4l2Device dev = yuyv_device();
    dev.max_buffers = 2;
    auto c = V4l2Capture::open(dev, {.width = 320, .height = 180});
    ASSERT_TRUE(c);
    dev.push_frame({yuyv_frame(dev, 40)});
    ASSERT_TRUE(c->poll());
    EXPECT_EQ(dev.queued_buffers(), 1) << "one held for the frame";
    dev.fail_qbuf(EIO);
    auto f = c->poll();
    ASSERT_TRUE(f) << f.error().message;
    EXPECT_EQ(c->errors(), 1u);
    EXPECT_EQ(c->last_error(), "VIDIOC_QBUF: Input/output error");
    EXPECT_EQ(dev.queued_buffers(), 1) << "the buffer stayed with the capture";
    ASSERT_TRUE(c->poll());
    EXPECT_EQ(dev.queued_buffers(), 2) << "and went back on the next poll: the driver is not left short";
}

}  // namespace
}  // namespace puddle::test
