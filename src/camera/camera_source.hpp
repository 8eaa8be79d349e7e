#pragma once
// Where camera frames come from: a small interface with one implementation per file (a V4L2 device,
// a mock that plays images), chosen by the device string: "mock:PATH" or a device path.

#include <cstdint>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>

#include "camera/camera_image.hpp"
#include "camera/v4l2_capture.hpp"
#include "camera/v4l2_io.hpp"
#include "util/result.hpp"

namespace puddle::camera {

// Faults a source absorbed without stopping, since it was opened (for health output and --stats).
struct SourceCounters {
    std::uint64_t dropped = 0;  // frames not shown: corrupt MJPEG, shorter than the format, driver-flagged
    std::uint64_t errors = 0;   // failed capture calls that were retried (EIO from VIDIOC_DQBUF, ...)
};

class CameraSource {
public:
    virtual ~CameraSource() = default;
    // Never blocks. `now` is the frame loop's time in seconds (the mock paces itself by it). Returns the
    // newest frame since the last call (valid until the next call), nothing when none is new, or an
    // error when the source is gone (the caller drops it and retries later).
    virtual Result<std::optional<CameraImage>> poll(double now) = 0;
    // One line for the log: device, format, size.
    virtual std::string describe() const = 0;
    virtual SourceCounters counters() const { return {}; }
};

// V4L2 streaming through `io` (MJPEG decoded here; YUYV and NV12 passed on for the GPU to convert).
// A frame that cannot be shown whole (corrupt MJPEG, a JPEG of another size, a buffer shorter than its
// format) is dropped, so the reflection keeps the previous one; drops and retried errors are counted
// and logged at most once a minute each (FaultTally), with poll's `now` as the clock.
Result<std::unique_ptr<CameraSource>> open_v4l2_source(V4l2Io& io, const CaptureRequest& request);
// "mock:PATH": an image, or a folder of images played in a loop at `fps` (name order). Errors exit 3.
// A stop requested through `stop` ends the decoding between two images, with an error.
Result<std::unique_ptr<CameraSource>> open_mock_source(const std::string& path, double fps,
                                                       std::stop_token stop = {});

// What a retry would find changed in a "mock:PATH", read without opening any image: the path's type, and
// for it (a folder: for it and each entry) the name, size, inode and modification and change times; or
// why it cannot be read (a missing path). Two equal stamps mean an open would fail the same way again.
std::string mock_source_stamp(const std::string& path);
// The stamp of what `request` opens: mock_source_stamp for "mock:PATH", prefixed with the device; empty
// for a V4L2 device, whose open can succeed without anything on disk changing (a busy camera freed).
std::string source_stamp(const CaptureRequest& request);

// request.device "mock:PATH" opens the mock, anything else a V4L2 device through io. Blocks: a UVC
// camera's VIDIOC_S_FMT or VIDIOC_STREAMON can take seconds, a mock folder as long to decode, so the
// frame loop calls this on a worker thread (systems/sky/camera_system.hpp); `stop` reaches the mock's
// decoding.
Result<std::unique_ptr<CameraSource>> open_camera_source(V4l2Io& io, const CaptureRequest& request,
                                                         std::stop_token stop = {});

}  // namespace puddle::camera
