// CameraSource "mock:PATH": one image, or a folder of images played in a loop at the requested frame
// rate, paced by the frame loop's time (so headless runs are repeatable). Stands in for a camera in
// the end-to-end test and on machines without one. Renaming or deleting the image or folder unplugs
// it: the next frame due is an error, as a V4L2 device that vanished from /dev is (the soak test's seam).
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include "assets/image_io.hpp"
#include "camera/camera_source.hpp"

namespace puddle::camera {

namespace {

// A mock folder is decoded into memory whole: bound it (256 frames of 640x360, or 32 of 1920x1080).
constexpr std::size_t mock_max_images = 256;
constexpr std::size_t mock_max_bytes = std::size_t{256} << 20;

// Every image matches the first one's size, and all of them up to `file` take at most `mock_max_bytes`
// (`bytes_so_far`) decoded.
Result<void> check_frame(const std::string& path, const std::string& file, int width, int height,
                         const assets::ImageInfo& first, std::size_t bytes_so_far) {
    if (width != first.width || height != first.height)
        return make_error(ExitCode::Asset,
                          "camera: mock:{}: {} is {}x{}, the first image is {}x{}; all must match", path,
                          file, width, height, first.width, first.height);
    if (bytes_so_far > mock_max_bytes)
        return make_error(ExitCode::Asset,
                          "camera: mock:{}: the images up to {} take {} MiB decoded; the limit is {} MiB",
                          path, file, bytes_so_far >> 20, mock_max_bytes >> 20);
    return {};
}

class MockSource final : public CameraSource {
public:
    MockSource(std::vector<assets::Image> frames, std::string path, double fps)
        : frames_(std::move(frames)), path_(std::move(path)), fps_(fps) {}

    Result<std::optional<CameraImage>> poll(double now) override {
        const auto tick = static_cast<std::int64_t>(std::floor(now * fps_));
        if (delivered_ && tick == last_tick_) return std::optional<CameraImage>{};
        if (access(path_.c_str(), F_OK) != 0)  // once per frame due; allocates nothing while it is there
            return make_error(ExitCode::Runtime, "camera: mock:{}: the device went away ({})", path_,
                              std::strerror(errno));
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

std::string mock_source_stamp(const std::string& path) {
    namespace fs = std::filesystem;
    const auto stamp_of = [](const std::string& name, std::string& out) {
        struct stat st {};
        if (::stat(name.c_str(), &st) != 0) {
            out += fmt::format("{}: {}\n", name, std::strerror(errno));
            return false;
        }
        out += fmt::format("{}: mode {:o} size {} inode {} modified {}.{} changed {}.{}\n", name, st.st_mode,
                           st.st_size, st.st_ino, st.st_mtim.tv_sec, st.st_mtim.tv_nsec, st.st_ctim.tv_sec,
                           st.st_ctim.tv_nsec);
        return S_ISDIR(st.st_mode);
    };
    std::string stamp;
    if (!stamp_of(path, stamp)) return stamp;
    // A folder: every entry, as open_mock_source lists them; sorted, as listing order is not stable.
    std::vector<std::string> entries;
    std::error_code ec;
    for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec))
        entries.push_back(it->path().string());
    if (ec) stamp += fmt::format("cannot list: {}\n", ec.message());
    std::sort(entries.begin(), entries.end());
    for (const std::string& entry : entries) stamp_of(entry, stamp);
    return stamp;
}

Result<std::unique_ptr<CameraSource>> open_mock_source(const std::string& path, double fps,
                                                       std::stop_token stop) {
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
    // Every header first (cheap: no pixel is decoded), so a folder that breaks a rule is refused
    // before the decode it would cost: on a small board, 16000x16000 PNGs take gigabytes.
    std::size_t bytes = 0;
    std::optional<assets::ImageInfo> first;
    for (const std::string& file : files) {
        if (stop.stop_requested())
            return make_error(ExitCode::Runtime, "camera: mock:{}: opening stopped before {}", path, file);
        auto header = assets::probe_image(file);
        if (!header) return make_error(ExitCode::Asset, "camera: mock: {}", header.error().message);
        if (!first) first = *header;
        if (auto fits = check_frame(path, file, header->width, header->height, *first,
                                    bytes += header->decoded_bytes());
            !fits)
            return fits.error();
    }
    std::vector<assets::Image> frames;
    bytes = 0;
    for (const std::string& file : files) {
        if (stop.stop_requested())  // shutting down: one image's decode is the longest wait
            return make_error(ExitCode::Runtime, "camera: mock:{}: opening stopped before {}", path, file);
        auto image = assets::read_image(file);
        if (!image) return make_error(ExitCode::Asset, "camera: mock: {}", image.error().message);
        // Again on the pixels, should a file have changed since its header was read.
        if (auto fits =
                check_frame(path, file, image->width, image->height, *first, bytes += image->data.size());
            !fits)
            return fits.error();
        frames.push_back(std::move(image).value());
    }
    return std::unique_ptr<CameraSource>(
        std::make_unique<MockSource>(std::move(frames), path, std::max(fps, 0.1)));
}

}  // namespace puddle::camera
