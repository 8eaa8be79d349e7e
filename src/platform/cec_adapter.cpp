#include "platform/cec_adapter.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/cec.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace puddle::platform {

namespace {

class SystemCecIo final : public CecIo {
public:
    int open(const char* path, int flags) override { return ::open(path, flags); }
    int close(int fd) override { return ::close(fd); }
    int ioctl(int fd, unsigned long request, void* arg) override { return ::ioctl(fd, request, arg); }
};

int xioctl(CecIo& io, int fd, unsigned long request, void* arg) {
    int rc;
    do rc = io.ioctl(fd, request, arg);
    while (rc < 0 && errno == EINTR);
    return rc;
}

constexpr std::uint8_t standby_opcode = 0x36;        // CEC_MSG_STANDBY
constexpr std::uint8_t image_view_on_opcode = 0x04;  // CEC_MSG_IMAGE_VIEW_ON
constexpr std::uint8_t active_source_opcode = 0x82;  // CEC_MSG_ACTIVE_SOURCE

}  // namespace

CecIo& system_cec_io() {
    static SystemCecIo io;
    return io;
}

std::string physical_address_text(std::uint16_t a) {
    return fmt::format("{:x}.{:x}.{:x}.{:x}", a >> 12, (a >> 8) & 0xf, (a >> 4) & 0xf, a & 0xf);
}

Result<CecAdapter> CecAdapter::open(CecIo& io, const std::string& path, std::string_view osd_name) {
    const int fd = io.open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) return make_error(ExitCode::Display, "cec: {}: cannot open: {}", path, std::strerror(errno));
    CecAdapter adapter(io, path, fd);
    cec_caps caps{};
    if (xioctl(io, fd, CEC_ADAP_G_CAPS, &caps) < 0)
        return make_error(ExitCode::Display, "cec: {}: CEC_ADAP_G_CAPS: {} (not a CEC adapter?)", path,
                          std::strerror(errno));
    std::uint32_t mode = CEC_MODE_INITIATOR;
    if (xioctl(io, fd, CEC_S_MODE, &mode) < 0)
        return make_error(ExitCode::Display, "cec: {}: CEC_S_MODE initiator: {}", path, std::strerror(errno));
    cec_log_addrs current{};
    if (xioctl(io, fd, CEC_ADAP_G_LOG_ADDRS, &current) < 0)
        return make_error(ExitCode::Display, "cec: {}: CEC_ADAP_G_LOG_ADDRS: {}", path, std::strerror(errno));
    if (current.num_log_addrs > 0) return adapter;  // configured already (by cec-ctl, or a TV box's daemon)
    if (!(caps.capabilities & CEC_CAP_LOG_ADDRS)) return adapter;  // the driver configures itself
    cec_log_addrs claim{};
    claim.cec_version = CEC_OP_CEC_VERSION_1_4;
    claim.num_log_addrs = 1;
    claim.vendor_id = CEC_VENDOR_ID_NONE;
    claim.flags = CEC_LOG_ADDRS_FL_ALLOW_UNREG_FALLBACK;
    const std::size_t n = std::min(osd_name.size(), sizeof claim.osd_name - 1);
    std::memcpy(claim.osd_name, osd_name.data(), n);
    claim.primary_device_type[0] = CEC_OP_PRIM_DEVTYPE_PLAYBACK;
    claim.log_addr_type[0] = CEC_LOG_ADDR_TYPE_PLAYBACK;
    claim.all_device_types[0] = CEC_OP_ALL_DEVTYPE_PLAYBACK;
    if (xioctl(io, fd, CEC_ADAP_S_LOG_ADDRS, &claim) < 0)
        return make_error(ExitCode::Display, "cec: {}: CEC_ADAP_S_LOG_ADDRS playback: {}", path,
                          std::strerror(errno));
    return adapter;
}

std::uint16_t CecAdapter::physical_address() const {
    std::uint16_t address = CEC_PHYS_ADDR_INVALID;
    if (xioctl(*io_, fd_.get(), CEC_ADAP_G_PHYS_ADDR, &address) < 0) return CEC_PHYS_ADDR_INVALID;
    return address;
}

std::uint8_t CecAdapter::logical_address() const {
    cec_log_addrs current{};
    if (xioctl(*io_, fd_.get(), CEC_ADAP_G_LOG_ADDRS, &current) < 0 || current.num_log_addrs == 0 ||
        current.log_addr[0] == CEC_LOG_ADDR_INVALID)
        return CEC_LOG_ADDR_UNREGISTERED;
    return current.log_addr[0];
}

Result<CecDelivery> CecAdapter::send(std::uint8_t destination, const std::uint8_t* body, std::size_t length,
                                     std::string_view what) {
    cec_msg msg{};
    msg.msg[0] = static_cast<std::uint8_t>(logical_address() << 4 | destination);
    std::memcpy(msg.msg + 1, body, length);
    msg.len = static_cast<std::uint32_t>(length + 1);
    if (xioctl(*io_, fd_.get(), CEC_TRANSMIT, &msg) < 0) {
        if (errno == ENONET)
            return make_error(ExitCode::Display,
                              "cec: {}: {}: no logical address yet (is the HDMI cable in a TV?)", path_,
                              what);
        return make_error(ExitCode::Display, "cec: {}: {}: CEC_TRANSMIT: {}", path_, what,
                          std::strerror(errno));
    }
    if (msg.tx_status & CEC_TX_STATUS_OK) return CecDelivery::acknowledged;
    if (msg.tx_status & (CEC_TX_STATUS_NACK | CEC_TX_STATUS_MAX_RETRIES)) return CecDelivery::no_answer;
    return make_error(ExitCode::Display, "cec: {}: {}: transmit status 0x{:02x} (bus error or timeout)",
                      path_, what, msg.tx_status);
}

Result<CecDelivery> CecAdapter::standby_tv() {
    const std::uint8_t body[] = {standby_opcode};
    return send(CEC_LOG_ADDR_TV, body, sizeof body, "<Standby>");
}

Result<CecDelivery> CecAdapter::wake_tv() {
    const std::uint8_t view_on[] = {image_view_on_opcode};
    auto delivered = send(CEC_LOG_ADDR_TV, view_on, sizeof view_on, "<Image View On>");
    if (!delivered) return delivered;
    const std::uint16_t address = physical_address();
    const std::uint8_t active[] = {active_source_opcode, static_cast<std::uint8_t>(address >> 8),
                                   static_cast<std::uint8_t>(address & 0xff)};
    if (auto r = send(CEC_LOG_ADDR_BROADCAST, active, sizeof active, "<Active Source>"); !r) return r.error();
    return delivered;
}

}  // namespace puddle::platform
