#pragma once
// A fake V4L2 capture device behind the I/O seam: a queue state machine with the habits of real
// drivers. It snaps the requested size to the nearest it offers and pads bytesperline, grants fewer
// buffers than asked, answers EAGAIN when nothing is ready, delivers error-flagged buffers and MJPEG
// frames of varying length when told to, interrupts calls with EINTR, can vanish mid-stream
// (ENODEV, POLLERR) and come back, and fails chosen calls with a chosen errno or poll event (EIO from
// VIDIOC_DQBUF after a USB hiccup, ENXIO, POLLHUP) once, a few times or until told otherwise. It
// counts descriptors and mappings, so tests can prove that nothing leaks. Sizes follow the kernel's
// v4l2_fill_pixfmt(): subsampled chroma rounds odd sizes up.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "camera/v4l2_io.hpp"

namespace puddle::test {

struct FakeFormat {
    std::uint32_t fourcc = 0;
    std::vector<std::pair<int, int>> sizes;  // discrete sizes
};

struct FakeFrame {
    std::vector<std::byte> payload;  // copied into the buffer; bytesused = its size
    bool error = false;              // V4L2_BUF_FLAG_ERROR
};

class FakeV4l2Device final : public camera::V4l2Io {
public:
    // Set before open: what the device is.
    std::string path = "/dev/video0";
    std::vector<FakeFormat> formats;
    int max_buffers = 2;          // granted even when more are asked for
    int row_padding = 64;         // bytesperline = packed row + this
    bool exports_dmabuf = false;  // VIDIOC_EXPBUF support
    int eintr_every = 3;          // every Nth ioctl is interrupted once (0: never)

    // Driving it.
    void push_frame(FakeFrame frame) { pending_.push_back(std::move(frame)); }
    void unplug() { present_ = false; }
    void replug() { present_ = true; }
    // The next `times` calls (-1: every call until set again) fail with `err`; VIDIOC_DQBUF fails although
    // poll said POLLIN, and the frame stays ready. err 0 ends a failure.
    void fail_dqbuf(int err, int times = 1) { dqbuf_failure_ = {err, times}; }
    void fail_qbuf(int err, int times = 1) { qbuf_failure_ = {err, times}; }
    // The next `times` polls report `revents` (POLLERR, POLLHUP) although the device is present.
    void poll_reports(short revents, int times = 1) { poll_event_ = {revents, times}; }

    // Checking it.
    int open_fds() const { return static_cast<int>(fds_.size()); }
    int live_mappings() const { return static_cast<int>(mappings_.size()); }
    int opens() const { return opens_; }
    int queued_buffers() const;
    int eintr_count() const { return eintrs_; }
    bool streaming() const { return streaming_; }
    int granted_buffers() const { return static_cast<int>(buffers_.size()); }
    std::uint32_t negotiated_fourcc() const { return fourcc_; }
    int negotiated_width() const { return width_; }
    int negotiated_height() const { return height_; }
    int bytes_per_line() const { return stride_; }
    int size_image() const { return size_image_; }

    int open(const char* path, int flags) override;
    int close(int fd) override;
    int ioctl(int fd, unsigned long request, void* arg) override;
    void* mmap(std::size_t length, int prot, int flags, int fd, off_t offset) override;
    int munmap(void* address, std::size_t length) override;
    int poll(pollfd* fds, nfds_t count, int timeout_ms) override;

private:
    struct Buffer {
        std::vector<std::byte> memory;
        bool queued = false;
        bool done = false;  // filled, waiting to be dequeued
        std::uint32_t bytesused = 0;
        bool error = false;
        std::uint32_t sequence = 0;
    };
    struct Injected {
        int value = 0;
        int times = 0;  // -1: until replaced
        bool take() {   // whether this call gets the injected value
            if (value == 0 || times == 0) return false;
            if (times > 0) --times;
            return true;
        }
    };
    int fail(int err);
    void deliver();  // moves pending frames into queued buffers
    bool present_ = true;
    int next_fd_ = 100;
    std::set<int> fds_;
    std::map<void*, std::size_t> mappings_;
    int opens_ = 0;
    int calls_ = 0;
    int eintrs_ = 0;
    std::uint32_t fourcc_ = 0;
    int width_ = 0, height_ = 0, stride_ = 0, size_image_ = 0;
    std::vector<Buffer> buffers_;
    std::deque<FakeFrame> pending_;
    std::deque<int> done_order_;
    bool streaming_ = false;
    std::uint32_t sequence_ = 0;
    Injected dqbuf_failure_, qbuf_failure_, poll_event_;
};

// A JPEG of a solid colour (libjpeg), so MJPEG frames have known content; quality changes its length.
std::vector<std::byte> encode_jpeg(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                   int quality = 90);
// `jpeg` cut in the middle of its entropy-coded data (after the last SOS marker), as when a USB transfer
// of the frame is lost: the headers are whole, libjpeg starts decoding and runs out of data.
std::vector<std::byte> cut_in_scan(const std::vector<std::byte>& jpeg);

}  // namespace puddle::test
