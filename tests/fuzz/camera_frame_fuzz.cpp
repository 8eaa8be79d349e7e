// Fuzz target: what checks a camera frame's size, stride and format before the GPU upload reads it. A
// fake V4L2 driver (tests/camera) reports a format, size and row padding taken from the input and then
// delivers frames of fuzzed length; V4l2Capture::open trusts what the driver wrote back and
// V4l2Capture::poll drops short frames (minimum_payload), and the V4L2 source decodes MJPEG. Every frame
// the source hands on must hold every byte the upload in systems/sky/camera_environment.cpp reads, with 4:2:0
// chroma at ceil(w/2) x ceil(h/2) samples, and rows no shorter than a packed row.
//
// Input: fourcc choice, width, height, row padding (signed), buffers, EINTR period, then frames as
// [length lo, length hi, flags, payload...].

#include <linux/videodev2.h>

#include <algorithm>
#include <vector>

#include "camera/camera_source.hpp"
#include "camera/fake_v4l2_device.hpp"
#include "camera/frame_layout.hpp"
#include "fuzz_support.hpp"

using namespace puddle;
using namespace puddle::camera;

namespace {

struct Reader {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    std::uint8_t byte() { return at < size ? data[at++] : 0; }
    std::size_t left() const { return size - at; }
};

std::size_t half_up(int n) {
    return (static_cast<std::size_t>(n) + 1) / 2;
}

// Bytes from the start of data that a tightly checked upload reads (GL reads the last row only to its end).
std::size_t upload_reads(const CameraImage& f) {
    const auto w = static_cast<std::size_t>(f.width), h = static_cast<std::size_t>(f.height);
    const auto stride = static_cast<std::size_t>(f.stride);
    switch (f.layout) {
        case PixelLayout::Rgba:
            return stride * (h - 1) + w * 4;
        case PixelLayout::Yuyv:
            return stride * (h - 1) + half_up(f.width) * 4;
        case PixelLayout::Nv12:
            return stride * h + stride * (half_up(f.height) - 1) + half_up(f.width) * 2;
    }
    return 0;
}

std::size_t packed_row(const CameraImage& f) {
    switch (f.layout) {
        case PixelLayout::Rgba:
            return static_cast<std::size_t>(f.width) * 4;
        case PixelLayout::Yuyv:
            return half_up(f.width) * 4;
        case PixelLayout::Nv12:
            return static_cast<std::size_t>(f.width);
    }
    return 0;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    fuzz::quiet_logs();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Reader in{data, size};
    constexpr std::uint32_t fourccs[] = {V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_MJPEG};
    const std::uint32_t fourcc = fourccs[in.byte() % 3];
    const int width = 1 + (in.byte() | (in.byte() & 1) << 8);  // 1 to 512
    const int height = 1 + (in.byte() | (in.byte() & 1) << 8);
    test::FakeV4l2Device device;
    device.formats = {{fourcc, {{width, height}}}};
    device.row_padding = static_cast<std::int8_t>(in.byte());
    device.max_buffers = 2 + in.byte() % 3;
    // 0 (never) or every 2nd to 4th call; 1 would interrupt every retry too, which no kernel does.
    const int eintr = in.byte() % 4;
    device.eintr_every = eintr == 0 ? 0 : eintr + 1;

    CaptureRequest request{.device = device.path, .width = width, .height = height, .buffers = 4};
    auto source = open_v4l2_source(device, request);
    if (!source) return 0;
    while (in.left() >= 3) {
        const std::size_t length = std::min<std::size_t>(in.byte() | in.byte() << 8, in.left() - 1);
        const bool error = in.byte() & 1;
        std::vector<std::byte> payload(length);
        std::copy_n(reinterpret_cast<const std::byte*>(data + in.at), std::min(length, in.left()),
                    payload.begin());
        in.at += std::min(length, in.left());
        device.push_frame({.payload = std::move(payload), .error = error});
        auto frame = (*source)->poll(0);
        if (!frame) break;  // the source reports a broken device; the caller reopens it
        if (!*frame) continue;
        const CameraImage& f = **frame;
        PUDDLE_FUZZ_CHECK(f.width > 0 && f.height > 0, "%s frame of %dx%d", layout_name(f.layout), f.width,
                          f.height);
        PUDDLE_FUZZ_CHECK(f.stride > 0 && static_cast<std::size_t>(f.stride) >= packed_row(f),
                          "%s %dx%d: bytesperline %d is shorter than a row (%zu bytes)",
                          layout_name(f.layout), f.width, f.height, f.stride, packed_row(f));
        PUDDLE_FUZZ_CHECK(f.data.size() >= upload_reads(f),
                          "%s %dx%d, bytesperline %d: the frame holds %zu bytes, the upload reads %zu",
                          layout_name(f.layout), f.width, f.height, f.stride, f.data.size(), upload_reads(f));
    }
    return 0;
}
