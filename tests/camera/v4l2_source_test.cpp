// Tests for src/camera/v4l2_source.cpp, the CameraSource over a V4L2 device, against the fake device:
// MJPEG frames decoded, corrupt ones dropped and counted, retried capture errors counted while the stream
// goes on, an unplugged device ending the stream with its error, shown frames numbered in order, and the
// start-up line that describes the stream.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "camera/camera_source.hpp"
#include "camera/fake_v4l2_device.hpp"

namespace puddle::test {
namespace {

FakeV4l2Device mjpeg_device() {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_MJPEG, {{64, 48}}}};
    dev.max_buffers = 3;
    return dev;
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

TEST(V4l2Source, CorruptMjpegFramesAreDroppedAndCounted) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_MJPEG, {{64, 48}}}};
    dev.max_buffers = 3;
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    const auto whole = encode_jpeg(64, 48, 200, 40, 30);
    dev.push_frame({whole});
    auto a = (*src)->poll(0.0);
    ASSERT_TRUE(a && a->has_value());
    dev.push_frame({cut_in_scan(whole)});
    auto b = (*src)->poll(0.1);
    ASSERT_TRUE(b) << "a corrupt frame does not end the stream";
    EXPECT_FALSE(b->has_value()) << "a truncated frame is not shown";
    EXPECT_EQ((*src)->counters().dropped, 1u);
    dev.push_frame({encode_jpeg(32, 24, 200, 40, 30)});
    auto c = (*src)->poll(0.2);
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->has_value()) << "a JPEG of another size than negotiated is not shown";
    EXPECT_EQ((*src)->counters().dropped, 2u);
    dev.push_frame({whole});
    auto d = (*src)->poll(0.3);
    ASSERT_TRUE(d && d->has_value());
    EXPECT_EQ((*src)->counters().dropped, 2u);
    EXPECT_EQ((*src)->counters().errors, 0u);
}

TEST(V4l2Source, RetriedCaptureErrorsAreCountedAndTheStreamGoesOn) {
    FakeV4l2Device dev = mjpeg_device();
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    dev.push_frame({encode_jpeg(64, 48, 200, 40, 30)});
    dev.fail_dqbuf(EIO, 2);
    for (double now : {0.0, 0.1}) {
        auto f = (*src)->poll(now);
        ASSERT_TRUE(f) << "EIO is retried: " << f.error().message;
        EXPECT_FALSE(f->has_value());
    }
    EXPECT_EQ((*src)->counters().errors, 2u);
    EXPECT_EQ((*src)->counters().dropped, 0u) << "an error is not a dropped frame";
    auto g = (*src)->poll(0.2);
    ASSERT_TRUE(g && g->has_value()) << "the frame waiting in the driver, on the next poll";
    EXPECT_EQ((*src)->counters().errors, 2u);
}

TEST(V4l2Source, AnUnpluggedDeviceEndsTheStreamWithItsError) {
    FakeV4l2Device dev = mjpeg_device();
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    dev.push_frame({encode_jpeg(64, 48, 200, 40, 30)});
    dev.fail_dqbuf(ENODEV);
    auto f = (*src)->poll(0.0);
    ASSERT_FALSE(f) << "ENODEV is not retried";
    EXPECT_EQ(f.error().message, std::string("camera: /dev/video0: VIDIOC_DQBUF: ") + std::strerror(ENODEV));
    EXPECT_EQ((*src)->counters().errors, 0u) << "not counted as a retried error";
}

TEST(V4l2Source, ShownFramesAreNumberedInOrder) {
    FakeV4l2Device dev = mjpeg_device();
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    const auto whole = encode_jpeg(64, 48, 200, 40, 30);
    std::vector<std::uint64_t> numbers;
    for (const auto& jpeg : {whole, cut_in_scan(whole), whole}) {
        dev.push_frame({jpeg});
        auto f = (*src)->poll(0.0);
        ASSERT_TRUE(f) << f.error().message;
        if (f->has_value()) numbers.push_back((*f)->sequence);
    }
    EXPECT_EQ(numbers, (std::vector<std::uint64_t>{1, 2})) << "a dropped frame takes no number";
}

// MJPEG is decoded to RGBA, 4 bytes a pixel, and JPEG (JFIF) is full range.
TEST(V4l2Source, DescribesTheNegotiatedStream) {
    FakeV4l2Device dev = mjpeg_device();
    auto src = camera::open_v4l2_source(dev, {.width = 64, .height = 48});
    ASSERT_TRUE(src) << src.error().message;
    EXPECT_EQ((*src)->describe(), "/dev/video0: MJPG 64x48 (" + std::to_string(64 * 4) + " bytes per row, " +
                                      std::to_string(dev.granted_buffers()) + " buffers, BT.601 full range)");
}

}  // namespace
}  // namespace puddle::test
