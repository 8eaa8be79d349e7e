#pragma once
// A fake V4L2 capture device behind the I/O seam: a queue state machine with the habits of real
// drivers. It snaps the requested size to the nearest it offers and pads bytesperline, grants fewer
// buffers than asked, answers EAGAIN when nothing is ready, delivers error-flagged buffers and MJPEG
// frames of varying length when told to, interrupts calls with EINTR, can vanish mid-stream
// (ENODEV, POLLERR) and come back, and fails chosen calls with a chosen errno or poll event (EIO from
// VIDIOC_DQBUF after a USB hiccup, ENXIO, POLLHUP) once, a few times or until told otherwise. It
// counts descriptors and mappings, so tests can prove that nothing leaks. Sizes follow the kernel's
// v4l2_fill_pixfmt(): subsampled chroma rounds odd sizes up. It can also hold a chosen ioctl until the
// test lets it go, as a UVC camera's VIDIOC_S_FMT or VIDIOC_STREAMON can block for seconds.
// Thread-safe, as a driver is: the camera system opens and closes on a worker thread while the test
// thread pushes frames and reads the counters. The settings above "Driving it" are set before the
// first open and not changed while a call may run.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
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
    void push_frame(FakeFrame frame) {
        const auto lock = guard();
        pending_.push_back(std::move(frame));
    }
    void unplug() { write(present_, false); }
    void replug() { write(present_, true); }
    // The next `times` calls (-1: every call until set again) fail with `err`; VIDIOC_DQBUF fails although
    // poll said POLLIN, and the frame stays ready. err 0 ends a failure.
    void fail_dqbuf(int err, int times = 1) { write(dqbuf_failure_, {err, times}); }
    void fail_qbuf(int err, int times = 1) { write(qbuf_failure_, {err, times}); }
    // The next `times` polls report `revents` (POLLERR, POLLHUP) although the device is present.
    void poll_reports(short revents, int times = 1) { write(poll_event_, {revents, times}); }
    // From now on each `request` (VIDIOC_STREAMON, ...) waits inside the call until release(). A call
    // that has waited `limit` goes on as usual and ends the hold, so a test of code that makes the call
    // on the test's own thread fails instead of hanging.
    void hold(unsigned long request, std::chrono::milliseconds limit = std::chrono::seconds(10));
    void release();

    // Checking it.
    int open_fds() const {
        const auto lock = guard();
        return static_cast<int>(fds_.size());
    }
    int live_mappings() const {
        const auto lock = guard();
        return static_cast<int>(mappings_.size());
    }
    int opens() const { return read(opens_); }
    int queued_buffers() const;
    int eintr_count() const { return read(eintrs_); }
    bool streaming() const { return read(streaming_); }
    int granted_buffers() const {
        const auto lock = guard();
        return static_cast<int>(buffers_.size());
    }
    std::uint32_t negotiated_fourcc() const { return read(fourcc_); }
    int negotiated_width() const { return read(width_); }
    int negotiated_height() const { return read(height_); }
    int bytes_per_line() const { return read(stride_); }
    int size_image() const { return read(size_image_); }
    int held_calls() const { return read(held_calls_); }  // waiting in hold() now

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
    struct Sync {  // behind a pointer, so the device stays movable
        std::mutex mutex;
        std::condition_variable released;
    };
    std::unique_lock<std::mutex> guard() const { return std::unique_lock(sync_->mutex); }
    template <class T>
    T read(const T& field) const {
        const auto lock = guard();
        return field;
    }
    template <class T>
    void write(T& field, std::type_identity_t<T> value) {
        const auto lock = guard();
        field = std::move(value);
    }
    int fail(int err);
    void deliver();  // moves pending frames into queued buffers
    std::unique_ptr<Sync> sync_ = std::make_unique<Sync>();
    std::optional<unsigned long> held_;  // the ioctl that waits
    std::chrono::milliseconds hold_limit_{0};
    int held_calls_ = 0;
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
