// Camera faults are counted and reported at most once a minute, by an injected clock.
#include "camera/fault_tally.hpp"

#include <gtest/gtest.h>

namespace puddle::test {
namespace {

TEST(FaultTally, TheFirstFaultAtOnceThenOneLinePerMinute) {
    camera::FaultTally tally("/dev/video0", "corrupt MJPEG frame dropped", "corrupt MJPEG frames dropped");
    EXPECT_EQ(tally.due(0.0), std::nullopt) << "nothing counted, nothing to say";
    EXPECT_EQ(
        tally.record(10.0, 1, "premature end of data"),
        "camera: /dev/video0: 1 corrupt MJPEG frame dropped in the last minute (premature end of data)");
    // Thirty frames a second for the rest of the minute: silence, only counting.
    int lines = 0;
    for (int i = 1; i < 30 * 59; ++i)
        lines += tally.record(10.0 + i / 30.0, 1, "premature end of data") ? 1 : 0;
    EXPECT_EQ(lines, 0);
    EXPECT_EQ(tally.due(69.99), std::nullopt);
    EXPECT_EQ(tally.due(70.0),
              "camera: /dev/video0: 1769 corrupt MJPEG frames dropped in the last minute "
              "(premature end of data)");
    EXPECT_EQ(tally.due(200.0), std::nullopt) << "reported faults are not reported again";
    EXPECT_EQ(tally.total(), 1770u);
    // Quiet for longer than a minute: the next fault is heard at once, with its own reason.
    EXPECT_EQ(
        tally.record(300.0, 2, "a 32x24 frame in a 64x48 stream"),
        "camera: /dev/video0: 2 corrupt MJPEG frames dropped in the last minute (a 32x24 frame in a 64x48 "
        "stream)");
    EXPECT_EQ(tally.record(301.0, 0, "unused"), std::nullopt) << "counting nothing says nothing";
    EXPECT_EQ(tally.total(), 1772u);
}

}  // namespace
}  // namespace puddle::test
