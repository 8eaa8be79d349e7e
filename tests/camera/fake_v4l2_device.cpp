#include "camera/fake_v4l2_device.hpp"

#include <linux/videodev2.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "camera/mjpeg_encoder.hpp"

namespace puddle::test {

int FakeV4l2Device::fail(int err) {
    errno = err;
    return -1;
}

int FakeV4l2Device::queued_buffers() const {
    std::lock_guard lock(sync_->mutex);
    return static_cast<int>(
        std::count_if(buffers_.begin(), buffers_.end(), [](const Buffer& b) { return b.queued; }));
}

void FakeV4l2Device::hold(unsigned long request, std::chrono::milliseconds limit) {
    std::lock_guard lock(sync_->mutex);
    held_ = request;
    hold_limit_ = limit;
}

void FakeV4l2Device::release() {
    {
        std::lock_guard lock(sync_->mutex);
        held_.reset();
    }
    sync_->released.notify_all();
}

int FakeV4l2Device::open(const char* p, int) {
    std::lock_guard lock(sync_->mutex);
    if (!present_ || path != p) return fail(ENOENT);
    ++opens_;
    const int fd = next_fd_++;
    fds_.insert(fd);
    return fd;
}

int FakeV4l2Device::close(int fd) {
    std::lock_guard lock(sync_->mutex);
    if (!fds_.erase(fd)) return fail(EBADF);
    if (fds_.empty()) {  // the last user gone: a driver frees its queue
        streaming_ = false;
        buffers_.clear();
        done_order_.clear();
    }
    return 0;
}

void FakeV4l2Device::deliver() {
    while (!pending_.empty()) {
        auto it = std::find_if(buffers_.begin(), buffers_.end(), [](const Buffer& b) { return b.queued; });
        if (it == buffers_.end()) return;  // the driver has nowhere to write: the frame waits
        FakeFrame f = std::move(pending_.front());
        pending_.pop_front();
        const std::size_t n = std::min(f.payload.size(), it->memory.size());
        std::copy_n(f.payload.begin(), n, it->memory.begin());
        it->bytesused = static_cast<std::uint32_t>(n);
        it->error = f.error;
        it->queued = false;
        it->done = true;
        it->sequence = sequence_++;
        done_order_.push_back(static_cast<int>(it - buffers_.begin()));
    }
}

int FakeV4l2Device::ioctl(int fd, unsigned long request, void* arg) {
    std::unique_lock lock(sync_->mutex);
    if (!fds_.count(fd)) return fail(EBADF);
    if (eintr_every > 0 && ++calls_ % eintr_every == 0) {
        ++eintrs_;
        return fail(EINTR);
    }
    if (held_ == request) {
        ++held_calls_;
        if (!sync_->released.wait_for(lock, hold_limit_, [&] { return held_ != request; }))
            held_.reset();  // waited long enough: the caller was never going to release it
        --held_calls_;
        if (!fds_.count(fd)) return fail(EBADF);
    }
    if (!present_) return fail(ENODEV);
    switch (request) {
        case VIDIOC_QUERYCAP: {
            auto* cap = static_cast<v4l2_capability*>(arg);
            *cap = {};
            std::strcpy(reinterpret_cast<char*>(cap->driver), "fake");
            cap->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_DEVICE_CAPS;
            cap->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
            return 0;
        }
        case VIDIOC_ENUM_FMT: {
            auto* d = static_cast<v4l2_fmtdesc*>(arg);
            if (d->index >= formats.size()) return fail(EINVAL);
            d->pixelformat = formats[d->index].fourcc;
            return 0;
        }
        case VIDIOC_ENUM_FRAMESIZES: {
            auto* s = static_cast<v4l2_frmsizeenum*>(arg);
            for (const FakeFormat& f : formats) {
                if (f.fourcc != s->pixel_format) continue;
                if (s->index >= f.sizes.size()) return fail(EINVAL);
                s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
                s->discrete.width = static_cast<std::uint32_t>(f.sizes[s->index].first);
                s->discrete.height = static_cast<std::uint32_t>(f.sizes[s->index].second);
                return 0;
            }
            return fail(EINVAL);
        }
        case VIDIOC_S_FMT: {
            if (streaming_ || !buffers_.empty()) return fail(EBUSY);
            auto& pix = static_cast<v4l2_format*>(arg)->fmt.pix;
            auto f = std::find_if(formats.begin(), formats.end(),
                                  [&](const FakeFormat& x) { return x.fourcc == pix.pixelformat; });
            if (f == formats.end()) f = formats.begin();  // drivers substitute rather than fail
            // The nearest size it has, by area difference.
            auto nearest = *std::min_element(f->sizes.begin(), f->sizes.end(), [&](auto a, auto b) {
                auto d = [&](std::pair<int, int> s) {
                    return std::abs(s.first * s.second - int(pix.width * pix.height));
                };
                return d(a) < d(b);
            });
            fourcc_ = f->fourcc;
            width_ = nearest.first;
            height_ = nearest.second;
            const int pairs = (width_ + 1) / 2, chroma_rows = (height_ + 1) / 2;
            if (fourcc_ == V4L2_PIX_FMT_YUYV) {
                stride_ = pairs * 4 + row_padding;
                size_image_ = stride_ * height_;
            } else if (fourcc_ == V4L2_PIX_FMT_NV12) {
                stride_ = pairs * 2 + row_padding;  // the chroma row of an odd width is one byte longer
                size_image_ = stride_ * (height_ + chroma_rows);
            } else {
                stride_ = 0;
                size_image_ = width_ * height_ * 2;  // room for any JPEG of this size
            }
            pix.pixelformat = fourcc_;
            pix.width = static_cast<std::uint32_t>(width_);
            pix.height = static_cast<std::uint32_t>(height_);
            pix.bytesperline = static_cast<std::uint32_t>(stride_);
            pix.sizeimage = static_cast<std::uint32_t>(size_image_);
            pix.colorspace = fourcc_ == V4L2_PIX_FMT_MJPEG ? V4L2_COLORSPACE_JPEG : V4L2_COLORSPACE_REC709;
            pix.ycbcr_enc = V4L2_YCBCR_ENC_DEFAULT;
            pix.quantization = V4L2_QUANTIZATION_DEFAULT;
            return 0;
        }
        case VIDIOC_G_PARM: {
            auto* p = static_cast<v4l2_streamparm*>(arg);
            p->parm.capture.capability = V4L2_CAP_TIMEPERFRAME;
            p->parm.capture.timeperframe = {1, 30};
            return 0;
        }
        case VIDIOC_S_PARM:
            return 0;
        case VIDIOC_REQBUFS: {
            auto* r = static_cast<v4l2_requestbuffers*>(arg);
            if (r->memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
            if (!mappings_.empty() && r->count > 0) return fail(EBUSY);
            r->count = std::min<std::uint32_t>(r->count, static_cast<std::uint32_t>(max_buffers));
            buffers_.assign(r->count, Buffer{});
            for (Buffer& b : buffers_) b.memory.assign(static_cast<std::size_t>(size_image_), std::byte{0});
            return 0;
        }
        case VIDIOC_QUERYBUF: {
            auto* b = static_cast<v4l2_buffer*>(arg);
            if (b->index >= buffers_.size()) return fail(EINVAL);
            b->length = static_cast<std::uint32_t>(buffers_[b->index].memory.size());
            b->m.offset = b->index * 0x100000u;
            return 0;
        }
        case VIDIOC_EXPBUF: {
            if (!exports_dmabuf) return fail(ENOTTY);
            auto* e = static_cast<v4l2_exportbuffer*>(arg);
            if (e->index >= buffers_.size()) return fail(EINVAL);
            e->fd = next_fd_++;
            fds_.insert(e->fd);
            return 0;
        }
        case VIDIOC_QBUF: {
            auto* b = static_cast<v4l2_buffer*>(arg);
            if (b->index >= buffers_.size()) return fail(EINVAL);
            Buffer& buf = buffers_[b->index];
            if (buf.queued || buf.done) return fail(EINVAL);  // queued twice: a bug in the caller
            if (qbuf_failure_.take()) return fail(qbuf_failure_.value);
            buf.queued = true;
            return 0;
        }
        case VIDIOC_DQBUF: {
            if (!streaming_) return fail(EINVAL);
            if (dqbuf_failure_.take()) return fail(dqbuf_failure_.value);
            deliver();
            if (done_order_.empty()) return fail(EAGAIN);
            const int i = done_order_.front();
            done_order_.pop_front();
            Buffer& buf = buffers_[static_cast<std::size_t>(i)];
            buf.done = false;
            auto* b = static_cast<v4l2_buffer*>(arg);
            b->index = static_cast<std::uint32_t>(i);
            b->bytesused = buf.bytesused;
            b->flags = buf.error ? V4L2_BUF_FLAG_ERROR : 0;
            b->sequence = buf.sequence;
            return 0;
        }
        case VIDIOC_STREAMON:
            streaming_ = true;
            return 0;
        case VIDIOC_STREAMOFF:
            streaming_ = false;
            for (Buffer& b : buffers_) b.queued = b.done = false;
            done_order_.clear();
            return 0;
        default:
            return fail(ENOTTY);
    }
}

void* FakeV4l2Device::mmap(std::size_t length, int, int, int fd, off_t offset) {
    std::lock_guard lock(sync_->mutex);
    if (!fds_.count(fd)) return (errno = EBADF, MAP_FAILED);
    if (!present_) return (errno = ENODEV, MAP_FAILED);
    const auto index = static_cast<std::size_t>(offset / 0x100000);
    if (index >= buffers_.size() || length != buffers_[index].memory.size())
        return (errno = EINVAL, MAP_FAILED);
    void* p = buffers_[index].memory.data();
    mappings_[p] = length;
    return p;
}

int FakeV4l2Device::munmap(void* address, std::size_t length) {
    std::lock_guard lock(sync_->mutex);
    auto it = mappings_.find(address);
    if (it == mappings_.end() || it->second != length) return fail(EINVAL);
    mappings_.erase(it);
    return 0;
}

int FakeV4l2Device::poll(pollfd* fds, nfds_t count, int) {
    std::lock_guard lock(sync_->mutex);
    int ready = 0;
    for (nfds_t i = 0; i < count; ++i) {
        fds[i].revents = 0;
        if (!fds_.count(fds[i].fd)) {
            fds[i].revents = POLLNVAL;
        } else if (!present_) {
            fds[i].revents = POLLERR;
        } else if (poll_event_.take()) {
            fds[i].revents = static_cast<short>(poll_event_.value);
        } else if (streaming_) {
            deliver();
            if (!done_order_.empty()) fds[i].revents = POLLIN;
        }
        if (fds[i].revents) ++ready;
    }
    return ready;
}

std::vector<std::byte> encode_jpeg(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                   int quality) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
            // A little texture in the lower half, so two qualities give two lengths.
            p[0] = (y >= height / 2 && x % 2 == 0) ? static_cast<std::uint8_t>(r ^ 0x20) : r;
            p[1] = g;
            p[2] = b;
        }
    return camera::encode_jpeg(rgb, width, height, quality);
}

std::vector<std::byte> cut_in_scan(const std::vector<std::byte>& jpeg) {
    std::size_t scan = 0;  // just after the last start-of-scan marker, FF DA
    for (std::size_t i = 0; i + 1 < jpeg.size(); ++i)
        if (jpeg[i] == std::byte{0xFF} && jpeg[i + 1] == std::byte{0xDA}) scan = i + 2;
    const std::size_t cut = scan + (jpeg.size() - scan) / 2;
    return std::vector<std::byte>(jpeg.begin(), jpeg.begin() + static_cast<std::ptrdiff_t>(cut));
}

}  // namespace puddle::test
