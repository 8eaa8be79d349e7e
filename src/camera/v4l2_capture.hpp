#pragma once
// V4L2 memory-mapped streaming capture on one device, non-blocking. open() negotiates the format (trusting
// the size, bytesperline and sizeimage the driver writes back, once they hold a whole frame: see
// frame_layout), maps the buffers the driver grants (often fewer than asked), queues them and starts
// the stream. poll() never blocks: it dequeues every ready buffer, keeps the newest and gives the
// others straight back, and drops (and counts) buffers flagged V4L2_BUF_FLAG_ERROR or shorter than a
// frame of the negotiated format. A vanished device (ENODEV, ENXIO, POLLERR, POLLHUP) is an error at
// once; any other failing call (EIO from VIDIOC_DQBUF after a USB hiccup) is counted and retried, and
// only reopen_after_errors of them in a row, with no frame between, are an error. The destructor stops
// the stream, unmaps every buffer and closes the descriptor, whatever state the device is in.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_image.hpp"
#include "camera/format_negotiation.hpp"
#include "camera/v4l2_io.hpp"
#include "util/result.hpp"

namespace puddle::camera {

// Failed capture calls in a row (no frame dequeued between) after which poll() gives up and the caller
// reopens the device: at 30 frames per second a third of a second of errors.
inline constexpr int reopen_after_errors = 10;

struct CaptureRequest {
    std::string device = "/dev/video0";
    int width = 1280, height = 720;
    double fps = 30.0;
    FormatPreference format = FormatPreference::Auto;
    int buffers = 4;
    bool export_dmabuf = false;  // VIDIOC_EXPBUF each buffer for zero-copy import
};

// A dequeued buffer, valid until the next poll() or the capture's end.
struct CapturedBuffer {
    std::uint32_t fourcc = 0;
    int index = -1;
    std::span<const std::byte> bytes;  // bytesused of the mapping
    int dmabuf_fd = -1;
    std::uint32_t sequence = 0;
};

class V4l2Capture {
public:
    static Result<V4l2Capture> open(V4l2Io& io, const CaptureRequest& request);
    V4l2Capture(V4l2Capture&&) noexcept = default;
    V4l2Capture& operator=(V4l2Capture&&) noexcept;
    V4l2Capture(const V4l2Capture&) = delete;
    V4l2Capture& operator=(const V4l2Capture&) = delete;
    ~V4l2Capture();

    int fd() const { return fd_.get(); }
    std::uint32_t fourcc() const { return fourcc_; }
    // The negotiated format as the driver wrote it back; data left empty.
    const CameraImage& format() const { return format_; }
    std::size_t buffer_count() const { return buffers_.size(); }
    // Buffers dropped since open (flagged by the driver, or too short), and why the last one was.
    std::uint64_t dropped() const { return dropped_; }
    const std::string& last_drop_reason() const { return last_drop_reason_; }
    // Failed calls retried since open (VIDIOC_DQBUF, VIDIOC_QBUF, poll), and the last one's
    // "VIDIOC_DQBUF: Input/output error".
    std::uint64_t errors() const { return errors_; }
    const std::string& last_error() const { return last_error_; }

    // The newest complete frame since the last call, nothing when none is ready (EAGAIN) or a call
    // failed and will be retried, or an error naming the device once it is gone or failed
    // reopen_after_errors times in a row. The previous frame's buffer is requeued first (with exported
    // dmabufs and 3 or more buffers, the one before it: the GPU may still read the last).
    Result<std::optional<CapturedBuffer>> poll();

private:
    V4l2Capture() = default;
    struct Buffer {
        Mapping memory;
        DeviceFd dmabuf;
    };
    int queue(int index);                            // 0, or the errno of VIDIOC_QBUF
    Result<void> requeue();                          // gives back every buffer in `returning_`
    Result<void> failed(const char* call, int err);  // an error once the device is gone or errors run on
    void drop(int index, std::string reason);
    void release();
    V4l2Io* io_ = nullptr;
    std::string path_;
    DeviceFd fd_;
    std::uint32_t fourcc_ = 0;
    CameraImage format_;
    std::vector<Buffer> buffers_;
    std::array<int, 2> held_{-1, -1};  // handed out: [1] the last frame, [0] the one before (zero-copy)
    int keep_ = 1;                     // buffers kept from the driver after poll(): 2 for zero-copy
    std::vector<int> returning_;       // buffers to give back to the driver (kept while QBUF fails)
    std::size_t frame_bytes_ = 1;      // the least bytesused of a whole frame (MJPEG: anything but empty)
    bool streaming_ = false;
    std::uint64_t dropped_ = 0;
    std::string last_drop_reason_;
    std::uint64_t errors_ = 0;
    int errors_in_a_row_ = 0;
    std::string last_error_;
};

}  // namespace puddle::camera
