// CameraSource over a V4L2 device: the capture state machine plus MJPEG decoding.
#include <fmt/format.h>
#include <linux/videodev2.h>
#include <spdlog/spdlog.h>

#include "camera/camera_source.hpp"
#include "camera/mjpeg_decoder.hpp"

namespace puddle::camera {

namespace {

class V4l2Source final : public CameraSource {
public:
    V4l2Source(V4l2Capture capture, std::string device)
        : capture_(std::move(capture)), device_(std::move(device)) {}

    Result<std::optional<CameraImage>> poll(double) override {
        auto polled = capture_.poll();
        if (!polled) return polled.error();
        if (!*polled) return std::optional<CameraImage>{};
        const CapturedBuffer& buf = **polled;
        CameraImage image = capture_.format();
        image.buffer_index = buf.index;
        image.sequence = ++sequence_;
        if (buf.fourcc == V4L2_PIX_FMT_MJPEG) {
            if (auto r = decoder_.decode(buf.bytes, image.width, image.height); !r) {
                // One bad frame is not a lost device: skip it, say so once.
                if (!warned_) spdlog::warn("{} (skipping bad frames)", r.error().message);
                warned_ = true;
                return std::optional<CameraImage>{};
            }
            image.data = decoder_.rgba();
            image.stride = image.width * 4;
            return std::optional<CameraImage>(image);
        }
        image.data = buf.bytes;
        image.dmabuf_fd = buf.dmabuf_fd;
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

private:
    V4l2Capture capture_;
    std::string device_;
    MjpegDecoder decoder_;
    std::uint64_t sequence_ = 0;
    bool warned_ = false;
};

}  // namespace

Result<std::unique_ptr<CameraSource>> open_v4l2_source(V4l2Io& io, const CaptureRequest& request) {
    auto capture = V4l2Capture::open(io, request);
    if (!capture) return capture.error();
    return std::unique_ptr<CameraSource>(
        std::make_unique<V4l2Source>(std::move(capture).value(), request.device));
}

Result<std::unique_ptr<CameraSource>> open_camera_source(V4l2Io& io, const CaptureRequest& request) {
    constexpr std::string_view mock = "mock:";
    if (request.device.starts_with(mock))
        return open_mock_source(request.device.substr(mock.size()), request.fps);
    return open_v4l2_source(io, request);
}

}  // namespace puddle::camera
