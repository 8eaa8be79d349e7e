#include "camera/v4l2_capture.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "camera/frame_layout.hpp"

namespace puddle::camera {

namespace {

YuvMatrix matrix_of(const v4l2_pix_format& f) {
    unsigned enc = f.ycbcr_enc;
    if (enc == V4L2_YCBCR_ENC_DEFAULT) enc = static_cast<unsigned>(V4L2_MAP_YCBCR_ENC_DEFAULT(f.colorspace));
    switch (enc) {
        case V4L2_YCBCR_ENC_709:
        case V4L2_YCBCR_ENC_XV709:
            return YuvMatrix::Bt709;
        case V4L2_YCBCR_ENC_BT2020:
        case V4L2_YCBCR_ENC_BT2020_CONST_LUM:
            return YuvMatrix::Bt2020;
        default:
            return YuvMatrix::Bt601;
    }
}

// What the driver says, or for "default" what V4L2 defines as default: full range only for JPEG.
bool full_range_of(const v4l2_pix_format& f) {
    if (f.quantization == V4L2_QUANTIZATION_DEFAULT) return f.colorspace == V4L2_COLORSPACE_JPEG;
    return f.quantization == V4L2_QUANTIZATION_FULL_RANGE;
}

PixelLayout layout_of(std::uint32_t fourcc) {
    if (fourcc == V4L2_PIX_FMT_YUYV) return PixelLayout::Yuyv;
    if (fourcc == V4L2_PIX_FMT_NV12) return PixelLayout::Nv12;
    return PixelLayout::Rgba;  // MJPEG: decoded to RGBA on the CPU
}

}  // namespace

Result<V4l2Capture> V4l2Capture::open(V4l2Io& io, const CaptureRequest& r) {
    V4l2Capture c;
    c.io_ = &io;
    c.path_ = r.device;
    const char* path = r.device.c_str();
    const int fd = io.open(path, O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return make_error(ExitCode::Runtime, "camera: {}: open: {}", r.device, std::strerror(errno));
    c.fd_ = DeviceFd(fd, {&io});

    v4l2_capability cap{};
    if (xioctl(io, fd, VIDIOC_QUERYCAP, &cap) != 0)
        return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_QUERYCAP: {} (not a V4L2 device?)", r.device,
                          std::strerror(errno));
    const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING))
        return make_error(ExitCode::Runtime, "camera: {}: not a video capture device with streaming I/O",
                          r.device);

    const std::vector<OfferedFormat> offered = enumerate_formats(io, fd);
    const auto chosen = choose_format(offered, r.format);
    if (!chosen)
        return make_error(ExitCode::Runtime,
                          "camera: {}: no format puddle can read ({}); the device offers: {}", r.device,
                          r.format == FormatPreference::Auto   ? "NV12, YUYV or MJPG"
                          : r.format == FormatPreference::Yuyv ? "YUYV was asked for"
                          : r.format == FormatPreference::Nv12 ? "NV12 was asked for"
                                                               : "MJPG was asked for",
                          describe_offer(offered));

    v4l2_format fmt{};
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    fmt.fmt.pix.width = static_cast<std::uint32_t>(r.width);
    fmt.fmt.pix.height = static_cast<std::uint32_t>(r.height);
    fmt.fmt.pix.pixelformat = *chosen;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    if (xioctl(io, fd, VIDIOC_S_FMT, &fmt) != 0)
        return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_S_FMT: format {} {}x{}: {}", r.device,
                          fourcc_name(*chosen), r.width, r.height, std::strerror(errno));
    // The driver may change anything; what it wrote back is the truth.
    const v4l2_pix_format& pix = fmt.fmt.pix;
    if (pix.pixelformat != *chosen)
        return make_error(
            ExitCode::Runtime, "camera: {}: VIDIOC_S_FMT: asked for {}, the driver gave {}; it offers: {}",
            r.device, fourcc_name(*chosen), fourcc_name(pix.pixelformat), describe_offer(offered));
    if (pix.width == 0 || pix.height == 0)
        return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_S_FMT: the driver gave an empty size",
                          r.device);
    if (pix.width > max_frame_side || pix.height > max_frame_side || pix.bytesperline > 4 * max_frame_side)
        return make_error(ExitCode::Runtime,
                          "camera: {}: VIDIOC_S_FMT: the driver gave {}x{} with bytesperline {}; at most {} "
                          "pixels a side are read",
                          r.device, pix.width, pix.height, pix.bytesperline, max_frame_side);
    c.fourcc_ = pix.pixelformat;
    c.format_ = CameraImage{.layout = layout_of(pix.pixelformat),
                            .width = static_cast<int>(pix.width),
                            .height = static_cast<int>(pix.height),
                            .stride = static_cast<int>(pix.bytesperline),
                            .matrix = matrix_of(pix),
                            .full_range = full_range_of(pix)};
    const bool compressed = pix.pixelformat == V4L2_PIX_FMT_MJPEG;
    if (c.format_.stride == 0)  // compressed formats and a few drivers leave it 0
        c.format_.stride = compressed                             ? static_cast<int>(pix.width) * 4
                           : pix.pixelformat == V4L2_PIX_FMT_YUYV ? static_cast<int>(pix.width + 1) / 2 * 4
                                                                  : static_cast<int>(pix.width);
    if (!compressed) {  // MJPEG frames vary in length; the decoder checks each one's size
        auto layout = frame_layout(c.format_.layout, c.format_.width, c.format_.height, c.format_.stride);
        if (!layout)
            return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_S_FMT gave {}", r.device,
                              layout.error().message);
        c.frame_bytes_ = layout->bytes;
    }

    // Frame rate: a request; drivers without it keep their own pace.
    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (r.fps > 0 && xioctl(io, fd, VIDIOC_G_PARM, &parm) == 0 &&
        (parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME)) {
        parm.parm.capture.timeperframe = {1000, static_cast<std::uint32_t>(std::lround(r.fps * 1000.0))};
        xioctl(io, fd, VIDIOC_S_PARM, &parm);
    }

    v4l2_requestbuffers req{};
    req.count = static_cast<std::uint32_t>(r.buffers);
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (xioctl(io, fd, VIDIOC_REQBUFS, &req) != 0)
        return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_REQBUFS: {}", r.device,
                          std::strerror(errno));
    if (req.count < 2)  // one buffer would be written while we read it
        return make_error(ExitCode::Runtime,
                          "camera: {}: VIDIOC_REQBUFS: the driver granted {} buffer(s), need 2", r.device,
                          req.count);
    c.buffers_.resize(req.count);
    for (std::uint32_t i = 0; i < req.count; ++i) {
        v4l2_buffer buf{};
        buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buf.memory = V4L2_MEMORY_MMAP;
        buf.index = i;
        if (xioctl(io, fd, VIDIOC_QUERYBUF, &buf) != 0)
            return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_QUERYBUF {}: {}", r.device, i,
                              std::strerror(errno));
        void* p =
            io.mmap(buf.length, PROT_READ | PROT_WRITE, MAP_SHARED, fd, static_cast<off_t>(buf.m.offset));
        if (p == MAP_FAILED)
            return make_error(ExitCode::Runtime, "camera: {}: mmap buffer {}: {}", r.device, i,
                              std::strerror(errno));
        c.buffers_[i].memory = Mapping(io, p, buf.length);
        if (buf.length < c.frame_bytes_)
            return make_error(ExitCode::Runtime, "camera: {}: buffer {} holds {} bytes; {} {}x{} needs {}",
                              r.device, i, buf.length, fourcc_name(c.fourcc_), c.format_.width,
                              c.format_.height, c.frame_bytes_);
        if (r.export_dmabuf) {
            v4l2_exportbuffer exp{};
            exp.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
            exp.index = i;
            exp.flags = O_RDONLY | O_CLOEXEC;
            if (xioctl(io, fd, VIDIOC_EXPBUF, &exp) == 0) c.buffers_[i].dmabuf = DeviceFd(exp.fd, {&io});
        }
    }
    // Zero-copy frames are read by the GPU after poll() returns: keep the previous one too, where
    // enough buffers remain with the driver.
    const bool all_exported = std::all_of(c.buffers_.begin(), c.buffers_.end(),
                                          [](const Buffer& b) { return static_cast<bool>(b.dmabuf); });
    c.keep_ = r.export_dmabuf && all_exported && req.count >= 3 ? 2 : 1;
    c.returning_.reserve(req.count);  // poll() then never allocates
    for (std::uint32_t i = 0; i < req.count; ++i)
        if (const int err = c.queue(static_cast<int>(i)); err != 0)
            return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_QBUF {}: {}", r.device, i,
                              std::strerror(err));
    v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (xioctl(io, fd, VIDIOC_STREAMON, &type) != 0)
        return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_STREAMON: {}", r.device,
                          std::strerror(errno));
    c.streaming_ = true;
    return c;
}

V4l2Capture& V4l2Capture::operator=(V4l2Capture&& o) noexcept {
    if (this != &o) {
        release();
        io_ = o.io_;
        path_ = std::move(o.path_);
        fd_ = std::move(o.fd_);
        fourcc_ = o.fourcc_;
        format_ = o.format_;
        buffers_ = std::move(o.buffers_);
        held_ = std::exchange(o.held_, {-1, -1});
        keep_ = o.keep_;
        returning_ = std::move(o.returning_);
        frame_bytes_ = o.frame_bytes_;
        streaming_ = std::exchange(o.streaming_, false);
        dropped_ = o.dropped_;
        last_drop_reason_ = std::move(o.last_drop_reason_);
        errors_ = o.errors_;
        errors_in_a_row_ = o.errors_in_a_row_;
        last_error_ = std::move(o.last_error_);
    }
    return *this;
}

V4l2Capture::~V4l2Capture() {
    release();
}

void V4l2Capture::release() {
    if (fd_ && streaming_) {
        v4l2_buf_type type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        xioctl(*io_, fd_.get(), VIDIOC_STREAMOFF, &type);  // fails harmlessly on a vanished device
    }
    streaming_ = false;
    held_ = {-1, -1};
    returning_.clear();
    buffers_.clear();  // unmaps and closes exported descriptors
    fd_.reset();
}

int V4l2Capture::queue(int index) {
    v4l2_buffer buf{};
    buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    buf.memory = V4L2_MEMORY_MMAP;
    buf.index = static_cast<std::uint32_t>(index);
    return xioctl(*io_, fd_.get(), VIDIOC_QBUF, &buf) == 0 ? 0 : errno;
}

Result<void> V4l2Capture::failed(const char* call, int err) {
    if (device_vanished(err))
        return make_error(ExitCode::Runtime, "camera: {}: {}: {}", path_, call, std::strerror(err));
    ++errors_;
    last_error_ = fmt::format("{}: {}", call, std::strerror(err));
    if (++errors_in_a_row_ < reopen_after_errors) return {};
    return make_error(ExitCode::Runtime, "camera: {}: {} ({} failed calls in a row)", path_, last_error_,
                      errors_in_a_row_);
}

Result<void> V4l2Capture::requeue() {
    // A buffer whose VIDIOC_QBUF fails stays here and is tried again on the next poll: dropping it would
    // leave the driver one buffer short for good, and after a few such failures with none to fill.
    Result<void> outcome;
    std::erase_if(returning_, [&](int index) {
        if (!outcome) return false;  // the device is gone or failing: keep the rest
        const int err = queue(index);
        if (err == 0) return true;
        outcome = failed("VIDIOC_QBUF", err);
        return false;
    });
    return outcome;
}

void V4l2Capture::drop(int index, std::string reason) {
    ++dropped_;
    last_drop_reason_ = std::move(reason);
    returning_.push_back(index);
}

Result<std::optional<CapturedBuffer>> V4l2Capture::poll() {
    if (!fd_) return make_error(ExitCode::Runtime, "camera: {}: not open", path_);
    // Give back what nobody reads any more: the last frame's buffer, or with zero-copy imports the one
    // before it (the GPU may still be sampling the last one; a frame later it is done).
    int& done = keep_ == 1 ? held_[1] : held_[0];
    if (done >= 0) returning_.push_back(std::exchange(done, -1));
    if (auto r = requeue(); !r) return r.error();
    pollfd p{.fd = fd_.get(), .events = POLLIN, .revents = 0};
    int n;
    do {
        n = io_->poll(&p, 1, 0);
    } while (n < 0 && errno == EINTR);
    if (n < 0) {
        if (auto r = failed("poll", errno); !r) return r.error();
        return std::optional<CapturedBuffer>{};
    }
    if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
        return make_error(ExitCode::Runtime, "camera: {}: the device went away (poll: {})", path_,
                          (p.revents & POLLHUP)    ? "POLLHUP"
                          : (p.revents & POLLNVAL) ? "POLLNVAL"
                                                   : "POLLERR");
    if (!(p.revents & POLLIN)) return std::optional<CapturedBuffer>{};

    // Drain the queue: the newest frame wins, older ones go straight back to the driver.
    std::optional<CapturedBuffer> newest;
    for (;;) {
        v4l2_buffer buf{};
        buf.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buf.memory = V4L2_MEMORY_MMAP;
        if (xioctl(*io_, fd_.get(), VIDIOC_DQBUF, &buf) != 0) {
            if (errno == EAGAIN) break;
            if (auto r = failed("VIDIOC_DQBUF", errno); !r) return r.error();
            break;  // retried on the next poll
        }
        errors_in_a_row_ = 0;
        const int index = static_cast<int>(buf.index);
        if (index < 0 || static_cast<std::size_t>(index) >= buffers_.size())
            return make_error(ExitCode::Runtime, "camera: {}: VIDIOC_DQBUF: buffer index {} out of range",
                              path_, index);
        const Mapping& memory = buffers_[static_cast<std::size_t>(index)].memory;
        const std::size_t used = std::min<std::size_t>(buf.bytesused, memory.size());
        if (buf.flags & V4L2_BUF_FLAG_ERROR) {
            drop(index, "the driver flagged the buffer (V4L2_BUF_FLAG_ERROR)");
            continue;
        }
        if (used < frame_bytes_) {
            drop(index, used == 0 ? std::string("an empty buffer")
                                  : fmt::format("{} bytes; {} {}x{} needs {}", used, fourcc_name(fourcc_),
                                                format_.width, format_.height, frame_bytes_));
            continue;
        }
        if (newest) returning_.push_back(newest->index);
        newest = CapturedBuffer{.fourcc = fourcc_,
                                .index = index,
                                .bytes = std::span(memory.data(), used),
                                .dmabuf_fd = buffers_[static_cast<std::size_t>(index)].dmabuf.get(),
                                .sequence = buf.sequence};
    }
    if (auto r = requeue(); !r) return r.error();  // dropped and older frames go back at once
    if (newest) {
        if (keep_ == 2) held_[0] = held_[1];
        held_[1] = newest->index;
    }
    return newest;
}

}  // namespace puddle::camera
