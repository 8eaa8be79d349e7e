#include "camera/format_negotiation.hpp"

#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include "camera/fake_v4l2_device.hpp"

namespace puddle::test {
namespace {

using namespace camera;

TEST(FormatNegotiation, AutoPrefersNv12ThenYuyvThenMjpeg) {
    const std::vector<OfferedFormat> all{
        {V4L2_PIX_FMT_MJPEG, {}}, {V4L2_PIX_FMT_YUYV, {}}, {V4L2_PIX_FMT_NV12, {}}};
    EXPECT_EQ(choose_format(all, FormatPreference::Auto), V4L2_PIX_FMT_NV12);
    EXPECT_EQ(choose_format({all[0], all[1]}, FormatPreference::Auto), V4L2_PIX_FMT_YUYV);
    EXPECT_EQ(choose_format({all[0]}, FormatPreference::Auto), V4L2_PIX_FMT_MJPEG);
    EXPECT_EQ(choose_format(all, FormatPreference::Mjpeg), V4L2_PIX_FMT_MJPEG);
    EXPECT_EQ(choose_format({all[0]}, FormatPreference::Yuyv), std::nullopt);
    EXPECT_EQ(choose_format({{V4L2_PIX_FMT_H264, {}}}, FormatPreference::Auto), std::nullopt);
}

TEST(FormatNegotiation, EnumeratesFormatsAndSizes) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_YUYV, {{640, 480}, {1280, 720}}}, {V4L2_PIX_FMT_MJPEG, {{1920, 1080}}}};
    const int fd = dev.open("/dev/video0", 0);
    ASSERT_GE(fd, 0);
    const auto offered = enumerate_formats(dev, fd);
    ASSERT_EQ(offered.size(), 2u);
    EXPECT_EQ(describe_offer(offered), "YUYV 640x480, 1280x720; MJPG 1920x1080");
    EXPECT_EQ(describe_offer({}), "nothing");
    dev.close(fd);
}

TEST(FormatNegotiation, DeviceOfferListsTheFormatsAndClosesTheDevice) {
    FakeV4l2Device dev;
    dev.formats = {{V4L2_PIX_FMT_NV12, {{320, 240}}}};
    auto offer = device_offer(dev, "/dev/video0");
    ASSERT_TRUE(offer) << offer.error().message;
    EXPECT_EQ(describe_offer(*offer), "NV12 320x240");
    EXPECT_EQ(dev.open_fds(), 0);
    dev.formats.clear();  // a node that captures nothing: no error, an empty offer
    auto none = device_offer(dev, "/dev/video0");
    ASSERT_TRUE(none) << none.error().message;
    EXPECT_TRUE(none->empty());
    dev.unplug();
    auto gone = device_offer(dev, "/dev/video0");
    ASSERT_FALSE(gone);
    EXPECT_NE(gone.error().message.find("/dev/video0: cannot open"), std::string::npos)
        << gone.error().message;
}

TEST(FormatNegotiation, FourccNames) {
    EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_YUYV), "YUYV");
    EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_NV12), "NV12");
    EXPECT_EQ(fourcc_name(V4L2_PIX_FMT_MJPEG), "MJPG");
}

}  // namespace
}  // namespace puddle::test
