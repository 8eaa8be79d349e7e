// CecAdapter against a fake kernel adapter behind the CecIo seam: the claim of a Playback address, the
// exact bytes of <Standby>, <Image View On> and <Active Source> (HDMI 1.4b CEC), a TV that does not
// answer, an adapter without a physical address, and errors that name the device.
#include "platform/cec_adapter.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/cec.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "support/fake_cec_adapter.hpp"

namespace puddle::platform {
namespace {

using test::FakeCecAdapter;
using Bytes = std::vector<std::uint8_t>;

TEST(CecAdapter, ClaimsAPlaybackAddressAsAnInitiator) {
    FakeCecAdapter fake;
    auto cec = CecAdapter::open(fake, "/dev/cec0", "Puddle rain display");
    ASSERT_TRUE(cec) << cec.error().message;
    EXPECT_EQ(fake.mode, static_cast<std::uint32_t>(CEC_MODE_INITIATOR));
    EXPECT_EQ(fake.claimed, 4) << "Playback 1";
    EXPECT_EQ(fake.claimed_name, "Puddle rain di") << "the OSD name is cut to the 14 characters CEC carries";
    EXPECT_EQ(cec->physical_address(), 0x1000);
    EXPECT_EQ(physical_address_text(cec->physical_address()), "1.0.0.0");
}

TEST(CecAdapter, StandbyAndWakeSendTheSpecsBytes) {
    FakeCecAdapter fake;
    auto cec = CecAdapter::open(fake, "/dev/cec0", "Puddle");
    ASSERT_TRUE(cec);
    auto off = cec->standby_tv();
    ASSERT_TRUE(off) << off.error().message;
    EXPECT_EQ(*off, CecDelivery::acknowledged);
    auto on = cec->wake_tv();
    ASSERT_TRUE(on) << on.error().message;
    EXPECT_EQ(*on, CecDelivery::acknowledged);
    ASSERT_EQ(fake.sent.size(), 3u);
    EXPECT_EQ(fake.sent[0], (Bytes{0x40, 0x36})) << "Playback 1 to TV: <Standby>";
    EXPECT_EQ(fake.sent[1], (Bytes{0x40, 0x04})) << "Playback 1 to TV: <Image View On>";
    EXPECT_EQ(fake.sent[2], (Bytes{0x4f, 0x82, 0x10, 0x00})) << "to all: <Active Source> 1.0.0.0";
}

TEST(CecAdapter, ATvThatDoesNotAnswerIsReportedNotAnError) {
    FakeCecAdapter fake;
    fake.tv_answers = false;
    auto cec = CecAdapter::open(fake, "/dev/cec0", "Puddle");
    ASSERT_TRUE(cec);
    auto off = cec->standby_tv();
    ASSERT_TRUE(off);
    EXPECT_EQ(*off, CecDelivery::no_answer);
}

TEST(CecAdapter, AnAddressClaimedByAnotherProgramIsUsedAsItIs) {
    FakeCecAdapter fake;
    fake.configured_elsewhere = true;
    auto cec = CecAdapter::open(fake, "/dev/cec0", "Puddle");
    ASSERT_TRUE(cec);
    EXPECT_EQ(fake.claimed, CEC_LOG_ADDR_INVALID) << "no second claim";
    ASSERT_TRUE(cec->standby_tv());
    ASSERT_EQ(fake.sent.size(), 1u);
    EXPECT_EQ(fake.sent[0], (Bytes{0x80, 0x36})) << "from Playback 2, the address it has";
}

TEST(CecAdapter, WithoutAPhysicalAddressSendingSaysWhy) {
    FakeCecAdapter fake;
    fake.physical = CEC_PHYS_ADDR_INVALID;  // hot-plug low: no TV, or it is off at the mains
    auto cec = CecAdapter::open(fake, "/dev/cec1", "Puddle");
    ASSERT_TRUE(cec) << "the claim waits in the kernel; opening still works";
    EXPECT_EQ(physical_address_text(cec->physical_address()), "f.f.f.f");
    auto off = cec->standby_tv();
    ASSERT_FALSE(off);
    EXPECT_EQ(off.error().message,
              "cec: /dev/cec1: <Standby>: no logical address yet (is the HDMI cable in a TV?)");
}

TEST(CecAdapter, AMissingDeviceIsAnErrorNamingIt) {
    FakeCecAdapter fake;
    fake.exists = false;
    auto cec = CecAdapter::open(fake, "/dev/cec3", "Puddle");
    ASSERT_FALSE(cec);
    EXPECT_EQ(cec.error().message, "cec: /dev/cec3: cannot open: No such file or directory");
}

TEST(CecAdapter, ClosesItsDescriptorOnceWhenMovedAndDestroyed) {
    FakeCecAdapter fake;
    {
        auto cec = CecAdapter::open(fake, "/dev/cec0", "Puddle");
        ASSERT_TRUE(cec);
        CecAdapter moved = std::move(*cec);
        EXPECT_EQ(fake.open_fds, 1);
    }
    EXPECT_EQ(fake.open_fds, 0);
}

TEST(CecAdapter, NotACecDeviceIsRefusedWhenOpened) {
    // The system seam on a file that is not a CEC adapter: the ioctl fails and the message says so.
    auto cec = CecAdapter::open(system_cec_io(), "/dev/null", "Puddle");
    ASSERT_FALSE(cec);
    EXPECT_NE(cec.error().message.find("cec: /dev/null: CEC_ADAP_G_CAPS"), std::string::npos)
        << cec.error().message;
    EXPECT_NE(cec.error().message.find("not a CEC adapter"), std::string::npos);
}

}  // namespace
}  // namespace puddle::platform
