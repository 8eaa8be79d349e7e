#pragma once
// A Raspberry Pi's power supply and throttling, as the kernel reports them, for the health message:
// - the raspberrypi-hwmon driver (hwmon device named "rpi_volt"): in0_lcrit_alarm is 1 while the firmware
//   saw under-voltage since the driver's last poll, every 2 s (Documentation/hwmon/raspberrypi-hwmon.rst);
// - the firmware's throttled flags, where the Raspberry Pi kernel exposes them
//   (/sys/devices/platform/soc/soc:firmware/get_throttled, hexadecimal, the bits of
//   `vcgencmd get_throttled`): 0 under-voltage now, 1 ARM frequency capped, 2 throttled, 3 soft
//   temperature limit; 16 to 19 the same, "has occurred" since the flags were last cleared.
// Boards without either report nothing, and Home Assistant is offered no sensor for them.
//
// BoardPowerWatch::poll is meant for about once a second: a dip shorter than the health interval is
// latched until the next take(), so it is not missed between two health messages. The firmware's
// "has occurred" bits count only beside the hwmon driver, which clears them every 2 s; alone they would
// hold since boot.

#include <cstdint>
#include <optional>
#include <string>

namespace puddle::remote {

// What was seen since the last take(); nullopt: this board does not report it.
struct BoardPower {
    std::optional<bool> undervoltage;
    std::optional<bool> throttled;  // frequency capped, throttled or at the soft temperature limit
};

// Where to read; tests point these at a folder of their own.
struct BoardPowerPaths {
    std::string hwmon_dir = "/sys/class/hwmon";
    std::string throttled_file = "/sys/devices/platform/soc/soc:firmware/get_throttled";
};

// The firmware's flags decoded (the bits above): under-voltage, and any kind of throttling, now or since.
BoardPower decode_throttled(std::uint32_t flags);

class BoardPowerWatch {
public:
    // Looks for the rpi_volt hwmon device and the throttled flags once (a few small sysfs reads).
    explicit BoardPowerWatch(const BoardPowerPaths& paths = {});

    // Whether the board reports either (Home Assistant's binary sensors exist only then).
    bool present() const { return !alarm_file_.empty() || has_throttled_; }
    // Reads the flags now and latches any under-voltage or throttling seen. No allocation, no blocking:
    // sysfs attributes, read into a fixed buffer.
    void poll();
    // What poll() saw since the last take(), then starts latching afresh.
    BoardPower take();

private:
    std::string alarm_file_;      // <hwmon>/in0_lcrit_alarm; empty: no rpi_volt device
    std::string throttled_file_;  // empty: none
    bool has_throttled_ = false;
    bool undervoltage_ = false, throttled_ = false;
};

}  // namespace puddle::remote
