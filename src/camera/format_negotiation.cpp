#include "camera/format_negotiation.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/videodev2.h>

#include <array>
#include <cerrno>
#include <cstring>

namespace puddle::camera {

std::string fourcc_name(std::uint32_t fourcc) {
    std::string s(4, ' ');
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>((fourcc >> (8 * i)) & 0xff);
        s[static_cast<std::size_t>(i)] = (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

std::vector<OfferedFormat> enumerate_formats(V4l2Io& io, int fd) {
    std::vector<OfferedFormat> offered;
    for (std::uint32_t i = 0;; ++i) {
        v4l2_fmtdesc desc{};
        desc.index = i;
        desc.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (xioctl(io, fd, VIDIOC_ENUM_FMT, &desc) != 0) break;
        OfferedFormat f{.fourcc = desc.pixelformat};
        for (std::uint32_t j = 0;; ++j) {
            v4l2_frmsizeenum size{};
            size.index = j;
            size.pixel_format = desc.pixelformat;
            if (xioctl(io, fd, VIDIOC_ENUM_FRAMESIZES, &size) != 0) break;
            if (size.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                f.sizes.push_back(fmt::format("{}x{}", size.discrete.width, size.discrete.height));
            } else {
                f.sizes.push_back(fmt::format("{}x{} to {}x{}", size.stepwise.min_width,
                                              size.stepwise.min_height, size.stepwise.max_width,
                                              size.stepwise.max_height));
                break;  // one range describes them all
            }
        }
        offered.push_back(std::move(f));
    }
    return offered;
}

std::optional<std::uint32_t> choose_format(const std::vector<OfferedFormat>& offered,
                                           FormatPreference preference) {
    std::vector<std::uint32_t> wanted;
    switch (preference) {
        case FormatPreference::Auto:
            wanted = {V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
            break;
        case FormatPreference::Yuyv:
            wanted = {V4L2_PIX_FMT_YUYV};
            break;
        case FormatPreference::Nv12:
            wanted = {V4L2_PIX_FMT_NV12};
            break;
        case FormatPreference::Mjpeg:
            wanted = {V4L2_PIX_FMT_MJPEG};
            break;
    }
    for (std::uint32_t w : wanted)
        for (const OfferedFormat& f : offered)
            if (f.fourcc == w) return w;
    return std::nullopt;
}

std::string describe_offer(const std::vector<OfferedFormat>& offered) {
    if (offered.empty()) return "nothing";
    std::string out;
    for (const OfferedFormat& f : offered) {
        if (!out.empty()) out += "; ";
        out += fourcc_name(f.fourcc);
        for (std::size_t i = 0; i < f.sizes.size(); ++i) out += (i == 0 ? " " : ", ") + f.sizes[i];
    }
    return out;
}

Result<std::vector<OfferedFormat>> device_offer(V4l2Io& io, const std::string& path) {
    const DeviceFd fd(io.open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC), {&io});
    if (!fd)
        return make_error(ExitCode::Runtime, "{}: cannot open: {}{}", path, std::strerror(errno),
                          errno == EACCES ? " (add the user to group video)" : "");
    return enumerate_formats(io, fd.get());
}

}  // namespace puddle::camera
