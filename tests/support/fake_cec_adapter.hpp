#pragma once
// A kernel CEC adapter behind platform::CecIo, as the kernel's CEC API documents it, with a TV that answers
// or not: for the CecAdapter tests and the display power tests.
#include <gtest/gtest.h>
#include <linux/cec.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "platform/cec_adapter.hpp"

namespace puddle::test {

// A kernel CEC adapter as the CEC API documents it, with a TV that answers or not.
class FakeCecAdapter final : public platform::CecIo {
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

}  // namespace puddle::test
