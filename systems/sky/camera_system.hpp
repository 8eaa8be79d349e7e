#pragma once
// The camera feed (input stage): opens the source that environment.camera_device names while
// environment.source = camera, polls it once per frame without blocking, and hands the newest frame
// to the GPU upload. Faults never stop the display: no device, or one that vanishes, means the
// cubemap, a one-line warning, and a new attempt every `camera_retry_seconds` until it streams again;
// a mock:PATH whose open failed is tried again only once its files have changed (camera::source_stamp).
// A change of device, size, rate or format reopens it; source = cubemap closes it.
//
// Opening and closing block (a UVC camera's VIDIOC_S_FMT or VIDIOC_STREAMON can take seconds, STREAMOFF
// too, and a mock folder of large images as long to decode), so they run on the feed's worker thread
// (DESIGN: nothing slow runs on the frame thread). While one is in flight the system returns at once
// and the puddle reflects the cubemap; the source it opens streams from the frame that collects it. A
// source is made on the worker and from then on used only on the frame thread, until it is handed back
// to the worker to close; the frame thread hands the worker a job only when the last one's result has
// been collected, so one job runs at a time, a close always comes before the next open of the same
// device, and a source opened for settings that changed meanwhile is closed and reopened, never polled.
// At start-up a mock:PATH opens on the caller's thread (a bad path is exit 3); a V4L2 device opens
// on the worker, so a slow camera does not hold back the first frame.
#include <memory>
#include <optional>
#include <string>

#include "camera/camera_source.hpp"
#include "params/param_store.hpp"
#include "systems/clock/frame_clock.hpp"
#include "systems/sky/camera_environment.hpp"
#include "util/background_job.hpp"

namespace puddle::systems {

inline constexpr double camera_retry_seconds = 1.0;

// What the worker hands back: the source opened for `request`, or why it could not be; `opened` is
// empty after a job that only closed a source.
struct CameraOpening {
    camera::CaptureRequest request;
    std::optional<Result<std::unique_ptr<camera::CameraSource>>> opened;
    std::string stamp;  // camera::source_stamp(request), taken before the open
};

// Resource.
struct CameraFeed {
    camera::V4l2Io* io = &camera::system_v4l2_io();  // tests put a fake device here; called from the worker
    std::unique_ptr<camera::CameraSource> source;
    camera::CaptureRequest request;  // what the open source was opened with
    double now = 0.0;                // frame-loop time, seconds
    double retry_at = 0.0;
    std::string last_failure;  // said once; repeats go to the debug log
    // The source_stamp of the last failed open: a retry that finds the same stamp is not tried, so a
    // mock folder that was refused is not read again until its files change.
    std::string failed_stamp;
    std::uint64_t open_attempts = 0;  // opens tried on the worker (retries skipped as unchanged not counted)
    std::uint64_t frames = 0;         // delivered since start-up
    std::uint64_t losses = 0;         // times a streaming source went away
    bool streaming() const { return source != nullptr; }

    camera::SourceCounters closed_faults;  // of the sources closed so far
    // Frames dropped and capture errors retried since start-up, the open source's included.
    camera::SourceCounters faults() const {
        const camera::SourceCounters open = source ? source->counters() : camera::SourceCounters{};
        return {.dropped = closed_faults.dropped + open.dropped,
                .errors = closed_faults.errors + open.errors};
    }

    // Opens and closes sources off the frame thread. Last member: destroyed first, it asks the job in
    // flight to stop and joins the worker. What bounds that wait: a mock folder stops decoding between
    // two images; a V4L2 call returns when its driver gives up (uvcvideo: each USB streaming control
    // transfer after 5 s, UVC_CTRL_STREAMING_TIMEOUT, and an open makes a few); past that, systemd's
    // stop timeout ends the process.
    BackgroundJob<CameraOpening> worker;
};

// What the parameters ask for.
camera::CaptureRequest camera_request(const params::Params& params);

// Start-up: opens a mock:PATH now, where a bad path is an asset error (exit 3); hands a V4L2 device to
// the worker, whose failure (a missing device) is no error: warned by the frame that collects it, retried.
Result<void> open_camera_feed(CameraFeed& feed, const params::Params& params);

// Once per frame; never waits for the worker.
void camera_feed_system(CameraFeed& feed, const params::Params& params, const ecs::FrameTime& time,
                        gpu::Device& device, CameraEnvironment& env);

}  // namespace puddle::systems
