// CameraSource "mock:PATH": one image, or a folder of images played in a loop at the requested frame
// rate, paced by the frame loop's time (so headless runs are repeatable). Stands in for a camera in
// the end-to-end test and on machines without one.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "assets/image_io.hpp"
#include "camera/camera_source.hpp"

namespace puddle::camera {

namespace {

// A mock folder is decoded into memory whole: bound it (256 frames of 640x360, or 32 of 1920x1080).
constexpr std::size_t mock_max_images = 256;
constexpr std::size_t mock_max_bytes = std::size_t{256} << 20;

class MockSource final : public CameraSource {
public:
    MockSource(std::vector<assets::Image> frames, std::string path, double fps)
        : frames_(std::move(frames)), path_(std::move(path)), fps_(fps) {}

    Result<std::optional<CameraImage>> poll(double now) override {
        const auto tick = static_cast<std::int64_t>(std::floor(now * fps_));
        if (delivered_ && tick == last_tick_) return std::optional<CameraImage>{};
        delivered_ = true;
        last_tick_ = tick;
        const assets::Image& f =
            frames_[static_cast<std::size_t>(tick % static_cast<std::int64_t>(frames_.size()))];
        return std::optional<CameraImage>(CameraImage{.layout = PixelLayout::Rgba,
                                                      .width = f.width,
                                                      .height = f.height,
                                                      .stride = f.width * 4,
                                                      .data = std::as_bytes(std::span(f.data)),
                                                      .full_range = true,
                                                      .sequence = ++sequence_});
    }

    std::string describe() const override {
        return fmt::format("mock:{}: {} image(s) of {}x{} at {} fps", path_, frames_.size(), frames_[0].width,
                           frames_[0].height, fps_);
    }

private:
    std::vector<assets::Image> frames_;
    std::string path_;
    double fps_;
    bool delivered_ = false;
    std::int64_t last_tick_ = 0;
    std::uint64_t sequence_ = 0;
};

}  // namespace

Result<std::unique_ptr<CameraSource>> open_mock_source(const std::string& path, double fps) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        for (const auto& entry : fs::directory_iterator(path, ec)) {
            if (!entry.is_regular_file()) continue;
            if (files.size() == mock_max_images)  // counted before any is decoded
                return make_error(ExitCode::Asset,
                                  "camera: mock:{}: the folder holds more than {} images; the limit is {}",
                                  path, mock_max_images, mock_max_images);
            files.push_back(entry.path().string());
        }
        std::sort(files.begin(), files.end());
        if (files.empty())
            return make_error(ExitCode::Asset, "camera: mock:{}: the folder holds no images", path);
    } else {
        files.push_back(path);
    }
    std::vector<assets::Image> frames;
    std::size_t bytes = 0;
    for (const std::string& file : files) {
        auto image = assets::read_image(file);
        if (!image) return make_error(ExitCode::Asset, "camera: mock: {}", image.error().message);
        if (!frames.empty() && (image->width != frames[0].width || image->height != frames[0].height))
            return make_error(ExitCode::Asset,
                              "camera: mock:{}: {} is {}x{}, the first image is {}x{}; all must match", path,
                              file, image->width, image->height, frames[0].width, frames[0].height);
        bytes += image->data.size();
        if (bytes > mock_max_bytes)
            return make_error(ExitCode::Asset,
                              "camera: mock:{}: the images up to {} take {} MiB decoded; the limit is {} MiB",
                              path, file, bytes >> 20, mock_max_bytes >> 20);
        frames.push_back(std::move(image).value());
    }
    return std::unique_ptr<CameraSource>(
        std::make_unique<MockSource>(std::move(frames), path, std::max(fps, 0.1)));
}

}  // namespace puddle::camera
