#include "systems/sky/camera_system.hpp"

#include <spdlog/spdlog.h>

namespace puddle::systems {

using params::ParamId;

namespace {

camera::FormatPreference format_preference(params::CameraFormat format) {
    switch (format) {
        case params::CameraFormat::yuyv:
            return camera::FormatPreference::Yuyv;
        case params::CameraFormat::nv12:
            return camera::FormatPreference::Nv12;
        case params::CameraFormat::mjpeg:
            return camera::FormatPreference::Mjpeg;
        case params::CameraFormat::automatic:
            break;
    }
    return camera::FormatPreference::Auto;
}

// Compared field by field each frame, so the steady state builds no strings.
bool still_requested(const params::Params& p, const camera::CaptureRequest& r) {
    return p.get<ParamId::environment_camera_device>() == r.device &&
           p.get<ParamId::environment_camera_width>() == r.width &&
           p.get<ParamId::environment_camera_height>() == r.height &&
           static_cast<double>(p.get<ParamId::environment_camera_fps>()) == r.fps &&
           format_preference(p.get<ParamId::environment_camera_format>()) == r.format;
}

bool wants_camera(const params::Params& params) {
    return params.get<ParamId::environment_source>() == params::EnvironmentSource::camera;
}

// The worker's job: close `closing` (STREAMOFF, munmap, close: before the open, which may need the
// same device), then open `request`. Only submitted while the worker is idle (see the header), so a
// job is never dropped unrun and a source is never closed on the frame thread.
void start_job(CameraFeed& feed, std::unique_ptr<camera::CameraSource> closing,
               std::optional<camera::CaptureRequest> request) {
    // shared_ptr only because std::function wants a copyable callable; the job holds the one reference.
    feed.worker.submit([io = feed.io, old = std::shared_ptr<camera::CameraSource>(std::move(closing)),
                        request = std::move(request),
                        failed_stamp = feed.failed_stamp](std::stop_token stop) mutable {
        old.reset();
        if (!request) return CameraOpening{};
        // Unchanged since it failed, it would fail the same way: a mock folder of images too large or of
        // mismatched sizes is not read again every second. `opened` stays empty: nothing was tried.
        std::string stamp = camera::source_stamp(*request);
        if (!stamp.empty() && stamp == failed_stamp)
            return CameraOpening{.request = std::move(*request), .stamp = std::move(stamp)};
        auto opened = camera::open_camera_source(*io, *request, std::move(stop));
        return CameraOpening{
            .request = std::move(*request), .opened = std::move(opened), .stamp = std::move(stamp)};
    });
}

// The source leaves the frame thread (the reflection goes back to the cubemap first, as its frames
// may be the driver's buffers); `reopen` names what to open once it is closed.
void close_feed(CameraFeed& feed, CameraEnvironment& env,
                std::optional<camera::CaptureRequest> reopen = std::nullopt) {
    drop_camera_frames(env);
    feed.closed_faults = feed.faults();
    start_job(feed, std::move(feed.source), std::move(reopen));
}

// One attempt, on the worker; retried `camera_retry_seconds` after it began if it fails.
void start_open(CameraFeed& feed, camera::CaptureRequest request) {
    feed.retry_at = feed.now + camera_retry_seconds;
    start_job(feed, nullptr, std::move(request));
}

// The worker's answer: a source to stream, or a failure logged once per distinct message.
void collect(CameraFeed& feed, CameraOpening done) {
    if (!done.opened) return;  // a close only, or a retry skipped as unchanged
    ++feed.open_attempts;
    auto& opened = *done.opened;
    if (!opened) {
        if (opened.error().message != feed.last_failure) {
            if (done.stamp.empty())
                spdlog::warn("{}; reflecting the cubemap, retrying every {:g} s", opened.error().message,
                             camera_retry_seconds);
            else
                spdlog::warn("{}; reflecting the cubemap, retrying when its files change",
                             opened.error().message);
        } else
            spdlog::debug("{}", opened.error().message);
        feed.last_failure = opened.error().message;
        feed.failed_stamp = std::move(done.stamp);
        return;
    }
    feed.source = std::move(opened).value();
    feed.request = std::move(done.request);
    feed.last_failure.clear();
    feed.failed_stamp.clear();
    spdlog::info("camera: streaming {}", feed.source->describe());
}

}  // namespace

camera::CaptureRequest camera_request(const params::Params& params) {
    return {.device = params.get<ParamId::environment_camera_device>(),
            .width = params.get<ParamId::environment_camera_width>(),
            .height = params.get<ParamId::environment_camera_height>(),
            .fps = params.get<ParamId::environment_camera_fps>(),
            .format = format_preference(params.get<ParamId::environment_camera_format>()),
            .export_dmabuf = true};
}

Result<void> open_camera_feed(CameraFeed& feed, const params::Params& params) {
    if (!wants_camera(params)) return {};
    const camera::CaptureRequest request = camera_request(params);
    if (request.device.starts_with("mock:")) {
        auto opened = camera::open_camera_source(*feed.io, request);
        if (!opened) return opened.error();
        feed.source = std::move(opened).value();
        feed.request = request;
        spdlog::info("camera: streaming {}", feed.source->describe());
        return {};
    }
    start_open(feed, request);
    return {};
}

void camera_feed_system(CameraFeed& feed, const params::Params& params, const ecs::FrameTime& time,
                        gpu::Device& device, CameraEnvironment& env) {
    feed.now += time.dt_seconds;
    if (auto done = feed.worker.take()) collect(feed, std::move(*done));
    if (feed.worker.busy()) return;  // an open or close in flight: the cubemap meanwhile
    if (!wants_camera(params)) {
        if (feed.source) {
            spdlog::info("camera: environment.source = cubemap; closing {}", feed.request.device);
            close_feed(feed, env);
        }
        return;
    }
    if (feed.source && !still_requested(params, feed.request)) {
        spdlog::info("camera: settings changed; reopening {}",
                     params.get<ParamId::environment_camera_device>());
        close_feed(feed, env, camera_request(params));
        feed.retry_at = feed.now + camera_retry_seconds;
        return;
    }
    if (!feed.source) {
        if (feed.now >= feed.retry_at) start_open(feed, camera_request(params));
        return;
    }
    auto polled = feed.source->poll(feed.now);
    if (!polled) {
        ++feed.losses;
        spdlog::warn("{}; back to the cubemap, retrying every {:g} s", polled.error().message,
                     camera_retry_seconds);
        feed.last_failure = polled.error().message;
        close_feed(feed, env);
        feed.retry_at = feed.now + camera_retry_seconds;
        return;
    }
    if (!*polled) return;
    ++feed.frames;
    if (auto r = upload_camera_frame(device, **polled, env); !r)
        spdlog::error("{}; reflecting the cubemap", r.error().message);
}

}  // namespace puddle::systems
