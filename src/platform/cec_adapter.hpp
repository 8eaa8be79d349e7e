#pragma once
// HDMI-CEC through the kernel's CEC API (/dev/cecN, linux/cec.h; kernel documentation
// "Linux Media Subsystem: CEC"): Puddle claims a Playback logical address and tells the TV to go to
// standby, or to wake and show this input. Messages and operands are those of HDMI 1.4b
// Supplement 1 (CEC): <Standby> 0x36, <Image View On> 0x04, <Active Source> 0x82 [physical address].
//
// Every call may block for as long as the bus takes (a message is retried up to 5 times by the kernel,
// about a second in the worst case), so callers keep this off the frame thread.

#include <poll.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "util/result.hpp"
#include "util/unique_fd.hpp"

namespace puddle::platform {

// The seam where the CEC code meets the kernel; tests give a fake adapter with the same contract
// (return -1 and set errno).
class CecIo {
public:
    virtual ~CecIo() = default;
    virtual int open(const char* path, int flags) = 0;
    virtual int close(int fd) = 0;
    virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
};
// The kernel: open(2), close(2), ioctl(2).
CecIo& system_cec_io();

// What became of one message.
enum class CecDelivery {
    acknowledged,  // the destination acknowledged it
    no_answer,     // nobody acknowledged it: the TV is off the bus, unplugged, or has CEC disabled
};

class CecAdapter {
public:
    // Opens `path` (/dev/cec0), becomes an initiator and claims a Playback logical address named
    // `osd_name` (at most 14 characters shown on the TV). An adapter already configured by another
    // program keeps its address and is used as it is.
    // Errors (ExitCode::Display): the device cannot be opened or is not a CEC adapter, or the claim is
    // refused; the message names the path and the ioctl.
    static Result<CecAdapter> open(CecIo& io, const std::string& path, std::string_view osd_name);

    // <Standby> to the TV (logical address 0).
    Result<CecDelivery> standby_tv();
    // <Image View On> to the TV, then <Active Source> with this adapter's physical address to all.
    // Delivery is the TV's answer to <Image View On>.
    Result<CecDelivery> wake_tv();

    const std::string& path() const { return path_; }
    // 0xffff until the sink's EDID gave one (the HDMI cable is plugged into a TV that is on).
    std::uint16_t physical_address() const;

private:
    CecAdapter(CecIo& io, std::string path, int fd) : io_(&io), path_(std::move(path)), fd_(fd, {&io}) {}
    Result<CecDelivery> send(std::uint8_t destination, const std::uint8_t* body, std::size_t length,
                             std::string_view what);
    std::uint8_t logical_address() const;
    CecIo* io_;
    std::string path_;
    BasicUniqueFd<CloseThrough<CecIo>> fd_;  // closed through io_, so the fake adapter sees it
};

// "1.0.0.0", as TVs and cec-ctl show a physical address; "f.f.f.f" when there is none.
std::string physical_address_text(std::uint16_t address);

}  // namespace puddle::platform
