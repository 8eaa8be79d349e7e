// CameraSource over a V4L2 device: the capture state machine plus MJPEG decoding.
#include <fmt/format.h>
#include <linux/videodev2.h>
#include <spdlog/spdlog.h>

#include "camera/camera_source.hpp"
#include "camera/fault_tally.hpp"
#include "camera/mjpeg_decoder.hpp"

namespace puddle::camera {

namespace {

class V4l2Source final : public CameraSource {
public:
    V4l2Source(V4l2Capture capture, std::string device)
        : capture_(std::move(capture)),
          device_(device),
          dropped_(device, fmt::format("corrupt {} frame dropped", format_name()),
                   fmt::format("corrupt {} frames dropped", format_name())),
          errors_(std::move(device), "capture error retried", "capture errors retried") {}

    Result<std::optional<CameraImage>> poll(double now) override {
        const std::uint64_t dropped = capture_.dropped(), errors = capture_.errors();
        auto polled = capture_.poll();
        report(errors_.record(now, capture_.errors() - errors, capture_.last_error()));
        report(dropped_.record(now, capture_.dropped() - dropped, capture_.last_drop_reason()));
        if (!polled) return polled.error();
        if (!*polled) return std::optional<CameraImage>{};
        const CapturedBuffer& buf = **polled;
        CameraImage image = capture_.format();
        image.buffer_index = buf.index;
        if (buf.fourcc == V4L2_PIX_FMT_MJPEG) {
            if (auto r = decoder_.decode(buf.bytes, image.width, image.height); !r) {
                // Not shown: the reflection keeps the last whole frame.
                report(dropped_.record(now, 1, r.error().message));
                return std::optional<CameraImage>{};
            }
            image.data = decoder_.rgba();
            image.stride = image.width * 4;
        } else {
            image.data = buf.bytes;
            image.dmabuf_fd = buf.dmabuf_fd;
        }
        image.sequence = ++sequence_;
        return std::optional<CameraImage>(image);
    }

    std::string describe() const override {
        const CameraImage& f = capture_.format();
        return fmt::format("{}: {} {}x{} ({} bytes per row, {} buffers, {} {} range)", device_,
                           fourcc_name(capture_.fourcc()), f.width, f.height, f.stride,
                           capture_.buffer_count(),
                           f.matrix == YuvMatrix::Bt709    ? "BT.709"
                           : f.matrix == YuvMatrix::Bt2020 ? "BT.2020"
                                                           : "BT.601",
                           f.full_range ? "full" : "limited");
    }

    SourceCounters counters() const override {
        return {.dropped = dropped_.total(), .errors = errors_.total()};
    }

private:
    std::string format_name() const {
        return capture_.fourcc() == V4L2_PIX_FMT_MJPEG ? "MJPEG" : fourcc_name(capture_.fourcc());
    }
    static void report(const std::optional<std::string>& line) {
        if (line) spdlog::warn("{}", *line);
    }

    V4l2Capture capture_;
    std::string device_;
    MjpegDecoder decoder_;
    FaultTally dropped_, errors_;
    std::uint64_t sequence_ = 0;
};

}  // namespace

Result<std::unique_ptr<CameraSource>> open_v4l2_source(V4l2Io& io, const CaptureRequest& request) {
    auto capture = V4l2Capture::open(io, request);
    if (!capture) return capture.error();
    return std::unique_ptr<CameraSource>(
        std::make_unique<V4l2Source>(std::move(capture).value(), request.device));
}

Result<std::unique_ptr<CameraSource>> open_camera_source(V4l2Io& io, const CaptureRequest& request,
                                                         std::stop_token stop) {
    constexpr std::string_view mock = "mock:";
    if (request.device.starts_with(mock))
        return open_mock_source(request.device.substr(mock.size()), request.fps, std::move(stop));
    return open_v4l2_source(io, request);
}

std::string source_stamp(const CaptureRequest& request) {
    constexpr std::string_view mock = "mock:";
    if (!request.device.starts_with(mock)) return {};
    return request.device + "\n" + mock_source_stamp(request.device.substr(mock.size()));
}

}  // namespace puddle::camera
