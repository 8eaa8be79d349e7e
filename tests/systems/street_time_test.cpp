// What the street's CPU side hands street.frag (systems/street/street_system.hpp): the lamps fade in at
// the far end of their row and out by the eye, so none pops as the street drifts a whole unit on, and a
// ripple's spot is on the ground in view.
#include <gtest/gtest.h>

#include "params/param_store.hpp"
#include "systems/street/street_system.hpp"

namespace puddle::test {
namespace {

TEST(StreetTime, ALampShowsFullyInTheRowAndFadesAtItsEnds) {
    constexpr int count = 10;
    EXPECT_FLOAT_EQ(systems::street_lamp(0, count, 0.0).w, 1.0f) << "the nearest, a unit away";
    EXPECT_FLOAT_EQ(systems::street_lamp(5, count, 0.5).w, 1.0f);
    EXPECT_FLOAT_EQ(systems::street_lamp(0, count, 0.9).x, 0.1f);
    EXPECT_FLOAT_EQ(systems::street_lamp(0, count, 0.9).w, 0.0f) << "passing the eye";
    EXPECT_FLOAT_EQ(systems::street_lamp(count - 1, count, 0.0).w, 0.0f) << "at the far end";
    const glm::vec4 lamp = systems::street_lamp(3, count, 0.25);
    EXPECT_FLOAT_EQ(lamp.x, 3.75f);
    EXPECT_FLOAT_EQ(lamp.y, 1 / 3.75f);
    EXPECT_FLOAT_EQ(lamp.z, (0.006f / 3.75f) * (0.006f / 3.75f));
}

// When the drift passes a whole unit, lamp i + 1 takes the place lamp i had: the row looks the same.
TEST(StreetTime, TheRowIsTheSameEitherSideOfAWholeUnitsDrift) {
    constexpr int count = 10;
    for (int i = 0; i + 1 < count; ++i) {
        const glm::vec4 before = systems::street_lamp(i + 1, count, 0.9999999);
        const glm::vec4 after = systems::street_lamp(i, count, 0.0);
        EXPECT_NEAR(before.x, after.x, 1e-5) << i;
        EXPECT_NEAR(before.w, after.w, 1e-4) << i;
    }
}

// A source's spot is a screen point below the horizon: back through ground_of's mapping it lies across
// the view and up to 0.9 of the way to the horizon.
TEST(StreetTime, ASourceFallsOnTheGroundInView) {
    constexpr float horizon = 0.42f, aspect = 16.0f / 9;
    for (int i = 0; i < 32; ++i)
        for (int repeat = 0; repeat < 5; ++repeat) {
            const glm::vec2 g =
                systems::street_source_spot(systems::street_ripple_kind, i, repeat, horizon, aspect);
            const double depth = 0.3 / g.y;
            const double x = g.x * depth / 0.3 / aspect + 0.5, y = horizon - horizon * depth;
            EXPECT_GE(x, 0.0);
            EXPECT_LE(x, 1.0);
            EXPECT_GE(y, -1e-6);
            EXPECT_LE(y, 0.9 * horizon + 1e-6);
        }
    EXPECT_NE(systems::street_source_spot(systems::street_ripple_kind, 3, 0, horizon, aspect),
              systems::street_source_spot(systems::street_ripple_kind, 3, 1, horizon, aspect))
        << "each repeat falls elsewhere";
}

}  // namespace
}  // namespace puddle::test
