#pragma once
// Which pixel format and size to ask a V4L2 device for: what it offers (VIDIOC_ENUM_FMT and
// VIDIOC_ENUM_FRAMESIZES), the config's preference, and a message listing the offer when nothing fits.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera/v4l2_io.hpp"
#include "util/result.hpp"

namespace puddle::camera {

// environment.camera_format (the camera system maps the parameter's enum): auto tries NV12, YUYV, then
// MJPEG (the YUV formats cost no CPU decode).
enum class FormatPreference { Auto, Yuyv, Nv12, Mjpeg };

struct OfferedFormat {
    std::uint32_t fourcc = 0;
    std::vector<std::string> sizes;  // "1280x720", or "160x120 to 1920x1080" for stepwise ranges
};

// "YUYV", "MJPG", "H264": the four characters of a V4L2 pixel format.
std::string fourcc_name(std::uint32_t fourcc);
// Everything the device at fd offers; empty when it enumerates nothing.
std::vector<OfferedFormat> enumerate_formats(V4l2Io& io, int fd);
// The first offered format the preference accepts, or nothing.
std::optional<std::uint32_t> choose_format(const std::vector<OfferedFormat>& offered,
                                           FormatPreference preference);
// "YUYV 640x480, 1280x720; H264 1920x1080", or "nothing" for an empty list.
std::string describe_offer(const std::vector<OfferedFormat>& offered);
// For `puddle --check`: opens the device at `path`, enumerates what it offers and closes it again; an
// error names the path and the reason. Empty for a node that captures nothing (a codec, a metadata node).
Result<std::vector<OfferedFormat>> device_offer(V4l2Io& io, const std::string& path);

}  // namespace puddle::camera
