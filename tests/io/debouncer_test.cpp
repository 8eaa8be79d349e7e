// Button debounce by edge timestamps.
#include "io/debouncer.hpp"

#include <gtest/gtest.h>

namespace puddle::io {
namespace {

TEST(Debouncer, AcceptsALevelOnlyAfterItHeld) {
    Debouncer d(0.020, false);
    d.edge(true, 1.000);
    EXPECT_FALSE(d.settle(1.010));
    EXPECT_FALSE(d.level());
    EXPECT_TRUE(d.settle(1.021));
    EXPECT_TRUE(d.level());
    EXPECT_FALSE(d.settle(1.030)) << "reported once";
}

TEST(Debouncer, BounceRestartsTheHoldTime) {
    Debouncer d(0.020, false);
    d.edge(true, 1.000);
    d.edge(false, 1.002);
    d.edge(true, 1.004);
    EXPECT_FALSE(d.settle(1.015));
    EXPECT_TRUE(d.settle(1.025));  // 21 ms after the last bounce
    EXPECT_TRUE(d.level());
}

TEST(Debouncer, AGlitchShorterThanTheHoldIsIgnored) {
    Debouncer d(0.020, false);
    d.edge(true, 1.000);
    d.edge(false, 1.005);
    EXPECT_FALSE(d.settle(1.100));
    EXPECT_FALSE(d.level());
}

}  // namespace
}  // namespace puddle::io
