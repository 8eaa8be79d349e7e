// A Raspberry Pi's under-voltage and throttling (remote/board_power.hpp) on a sysfs tree made here: the
// rpi_volt hwmon's alarm, the firmware's throttled flags, latching between health messages, and nothing
// on a board that has neither.
#include "remote/board_power.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "remote/health.hpp"
#include "support/test_support.hpp"

namespace puddle::remote {
namespace {

struct Sysfs {
    test::TempDir dir;
    BoardPowerPaths paths{(dir / "hwmon").string(), (dir / "get_throttled").string()};

    Sysfs() { std::filesystem::create_directories(dir / "hwmon"); }
    // A hwmon device named `name`, with an under-voltage alarm.
    void hwmon(const std::string& device, const std::string& name, const std::string& alarm) {
        std::filesystem::create_directories(dir / "hwmon" / device);
        dir.write("hwmon/" + device + "/name", name + "\n");
        dir.write("hwmon/" + device + "/in0_lcrit_alarm", alarm + "\n");
    }
    void alarm(const std::string& device, const std::string& value) {
        dir.write("hwmon/" + device + "/in0_lcrit_alarm", value + "\n");
    }
    void throttled(const std::string& flags) { dir.write("get_throttled", flags + "\n"); }
};

TEST(BoardPower, ABoardWithNeitherReportsNothing) {
    Sysfs fs;
    fs.hwmon("hwmon0", "cpu_thermal", "1");  // another device's alarm is not the supply's
    BoardPowerWatch watch(fs.paths);
    EXPECT_FALSE(watch.present());
    watch.poll();
    const BoardPower p = watch.take();
    EXPECT_FALSE(p.undervoltage);
    EXPECT_FALSE(p.throttled);
    const std::string doc = health_document({.undervoltage = p.undervoltage, .throttled = p.throttled});
    EXPECT_EQ(doc.find("undervoltage"), std::string::npos) << doc;
    EXPECT_EQ(doc.find("throttled"), std::string::npos) << doc;
}

// A dip between two health messages is latched by the once-a-second poll, reported once, then cleared.
TEST(BoardPower, TheHwmonAlarmIsLatchedUntilTaken) {
    Sysfs fs;
    fs.hwmon("hwmon0", "cpu_thermal", "0");
    fs.hwmon("hwmon1", "rpi_volt", "0");
    BoardPowerWatch watch(fs.paths);
    ASSERT_TRUE(watch.present());
    watch.poll();
    EXPECT_EQ(watch.take().undervoltage, false);
    fs.alarm("hwmon1", "1");
    watch.poll();
    fs.alarm("hwmon1", "0");
    watch.poll();
    const BoardPower dip = watch.take();
    EXPECT_EQ(dip.undervoltage, true) << "the dip between two messages";
    EXPECT_FALSE(dip.throttled) << "no firmware flags on this board";
    watch.poll();
    EXPECT_EQ(watch.take().undervoltage, false);
    const std::string doc = health_document({.undervoltage = dip.undervoltage});
    EXPECT_NE(doc.find("\"undervoltage\":true"), std::string::npos) << doc;
}

TEST(BoardPower, TheFirmwareFlagsDecodeAsVcgencmdDocumentsThem) {
    EXPECT_EQ(decode_throttled(0x0).undervoltage, false);
    EXPECT_EQ(decode_throttled(0x0).throttled, false);
    EXPECT_EQ(decode_throttled(0x1).undervoltage, true);
    EXPECT_EQ(decode_throttled(0x1).throttled, false);
    EXPECT_EQ(decode_throttled(0x4).throttled, true);         // throttled now
    EXPECT_EQ(decode_throttled(0x8).throttled, true);         // soft temperature limit
    EXPECT_EQ(decode_throttled(0x10000).undervoltage, true);  // has occurred
    EXPECT_EQ(decode_throttled(0x40000).throttled, true);     // throttling has occurred
    EXPECT_EQ(decode_throttled(0x50005).undervoltage, true);
}

// Beside the hwmon driver (which clears them every 2 s) the "has occurred" bits count; alone they hold
// since boot, so only the bits for now do.
TEST(BoardPower, TheStickyBitsCountOnlyBesideTheHwmonDriver) {
    Sysfs alone;
    alone.throttled("0x50000");
    BoardPowerWatch watch(alone.paths);
    ASSERT_TRUE(watch.present());
    watch.poll();
    BoardPower p = watch.take();
    EXPECT_EQ(p.undervoltage, false);
    EXPECT_EQ(p.throttled, false);
    alone.throttled("0x4");
    watch.poll();
    alone.throttled("0x0");
    watch.poll();
    p = watch.take();
    EXPECT_EQ(p.throttled, true);
    EXPECT_EQ(p.undervoltage, false);

    Sysfs with_hwmon;
    with_hwmon.hwmon("hwmon3", "rpi_volt", "0");
    with_hwmon.throttled("0x50000");
    BoardPowerWatch both(with_hwmon.paths);
    both.poll();
    p = both.take();
    EXPECT_EQ(p.undervoltage, true);
    EXPECT_EQ(p.throttled, true);
}

TEST(BoardPower, AFlagsFileThatIsNoNumberIsNoBoardPower) {
    Sysfs fs;
    fs.throttled("garbage");
    BoardPowerWatch watch(fs.paths);
    EXPECT_FALSE(watch.present());
}

}  // namespace
}  // namespace puddle::remote
