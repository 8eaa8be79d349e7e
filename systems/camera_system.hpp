#pragma once
// The camera feed (input stage): opens the source that environment.camera_device names while
// environment.source = camera, polls it once per frame without blocking, and hands the newest frame
// to the GPU upload. Faults never stop the display: no device, or one that vanishes, means the
// cubemap, a one-line warning, and a new attempt every `camera_retry_seconds` until it streams again.
// A change of device, size, rate or format reopens it; source = cubemap closes it.

#include <memory>
#include <string>

#include "camera/camera_source.hpp"
#include "params/param_store.hpp"
#include "systems/camera_environment.hpp"
#include "systems/frame_clock.hpp"

namespace puddle::systems {

inline constexpr double camera_retry_seconds = 1.0;

// Resource.
struct CameraFeed {
    camera::V4l2Io* io = &camera::system_v4l2_io();  // tests put a fake device here
    std::unique_ptr<camera::CameraSource> source;
    camera::CaptureRequest request;  // what the open source was opened with
    double now = 0.0;                // frame-loop time, seconds
    double retry_at = 0.0;
    std::string last_failure;  // said once; repeats go to the debug log
    std::uint64_t frames = 0;  // delivered since start-up
    std::uint64_t losses = 0;  // times a streaming source went away
    bool streaming() const { return source != nullptr; }

    camera::SourceCounters closed_faults;  // of the sources closed so far
    // Frames dropped and capture errors retried since start-up, the open source's included.
    camera::SourceCounters faults() const {
        const camera::SourceCounters open = source ? source->counters() : camera::SourceCounters{};
        return {.dropped = closed_faults.dropped + open.dropped,
                .errors = closed_faults.errors + open.errors};
    }
};

// What the parameters ask for.
camera::CaptureRequest camera_request(const params::Params& params);

// Opens the source now. Used at start-up, where a bad mock:PATH is an asset error (exit 3); a missing
// V4L2 device is not an error (warned, retried).
Result<void> open_camera_feed(CameraFeed& feed, const params::Params& params);

void camera_feed_system(CameraFeed& feed, const params::Params& params, const FrameClock& clock,
                        gpu::Device& device, CameraEnvironment& env);

}  // namespace puddle::systems
