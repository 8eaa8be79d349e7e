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

namespace puddle::platform {
namespace {

// A kernel CEC adapter as the CEC API documents it, with a TV that answers or not.
class FakeCecAdapter final : public CecIo {
public:
    bool exists = true;
    bool tv_answers = true;
    bool configured_elsewhere = false;  // another program claimed an address already
    std::uint16_t physical = 0x1000;    // 1.0.0.0: HDMI 1 of the TV
    std::uint8_t claimed = CEC_LOG_ADDR_INVALID;
    std::string claimed_name;
    std::uint32_t mode = 0;
    std::vector<std::vector<std::uint8_t>> sent;
    int open_fds = 0;

    int open(const char*, int) override {
        if (!exists) {
            errno = ENOENT;
            return -1;
        }
        ++open_fds;
        return 7;
    }
    int close(int) override {
        --open_fds;
        return 0;
    }
    int ioctl(int fd, unsigned long request, void* arg) override {
        EXPECT_EQ(fd, 7);
        switch (request) {
            case CEC_ADAP_G_CAPS: {
                auto* caps = static_cast<cec_caps*>(arg);
                *caps = {};
                std::strcpy(caps->driver, "fake");
                caps->capabilities = CEC_CAP_LOG_ADDRS | CEC_CAP_TRANSMIT | CEC_CAP_PHYS_ADDR;
                caps->available_log_addrs = 1;
                return 0;
            }
            case CEC_S_MODE:
                mode = *static_cast<std::uint32_t*>(arg);
                return 0;
            case CEC_ADAP_G_PHYS_ADDR:
                *static_cast<std::uint16_t*>(arg) = physical;
                return 0;
            case CEC_ADAP_G_LOG_ADDRS: {
                auto* l = static_cast<cec_log_addrs*>(arg);
                *l = {};
                if (configured_elsewhere) {
                    l->num_log_addrs = 1;
                    l->log_addr[0] = 8;  // Playback 2
                } else if (claimed != CEC_LOG_ADDR_INVALID) {
                    l->num_log_addrs = 1;
                    l->log_addr[0] = claimed;
                }
                return 0;
            }
            case CEC_ADAP_S_LOG_ADDRS: {
                auto* l = static_cast<cec_log_addrs*>(arg);
                if (l->num_log_addrs != 1 || l->log_addr_type[0] != CEC_LOG_ADDR_TYPE_PLAYBACK) {
                    errno = EINVAL;
                    return -1;
                }
                claimed_name = l->osd_name;
                // Without a physical address the kernel claims later; the address stays invalid until then.
                claimed = physical == CEC_PHYS_ADDR_INVALID ? CEC_LOG_ADDR_INVALID : 4;  // Playback 1
                l->log_addr[0] = claimed;
                return 0;
            }
            case CEC_TRANSMIT: {
                auto* m = static_cast<cec_msg*>(arg);
                if (claimed == CEC_LOG_ADDR_INVALID && !configured_elsewhere) {
                    errno = ENONET;
                    return -1;
                }
                sent.emplace_back(m->msg, m->msg + m->len);
                const bool broadcast = (m->msg[0] & 0xf) == 0xf;
                m->tx_status = broadcast || tv_answers ? CEC_TX_STATUS_OK
                                                       : CEC_TX_STATUS_NACK | CEC_TX_STATUS_MAX_RETRIES;
                return 0;
            }
            default:
                errno = ENOTTY;
                return -1;
        }
    }
};

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
