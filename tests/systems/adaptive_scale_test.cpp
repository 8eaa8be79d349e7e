// The adaptive scale in a running engine (systems/output/adaptive_scale.hpp): on llvmpipe a frame of the
// puddle takes several milliseconds even at 480x270 (the 512x512 wave step alone is about 4 ms on the
// development machine), so a 240 fps target is missed at any scale and drives the scale down; a 1 fps
// target is met at any scale and leaves it alone. The decision window is shortened to a quarter second
// so the test takes a few seconds; the controller's timing is tested on synthetic loads in
// tests/systems/scale_controller_test.cpp.
#include "systems/output/adaptive_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu_fixture.hpp"
#include "support/log_lines.hpp"
#include "support/test_support.hpp"
#include "systems/output/output_canvas.hpp"

namespace puddle::test {
namespace {

constexpr glm::ivec2 size{480, 270};

TEST(AdaptiveScale, HeadlessIsOffByDefaultAndRendersAtRenderScale) {
    auto engine = make_engine(make_params({"render.scale=0.75"}), size);
    ASSERT_TRUE(engine);
    render_frames(*engine, 5);
    const auto& adaptive = engine->world().resource<systems::AdaptiveScale>();
    EXPECT_EQ(adaptive.target_fps, 0.0) << "render.target_fps -1 on a display without a refresh: off";
    EXPECT_FALSE(adaptive.controller.has_value());
    EXPECT_EQ(adaptive.scale, 0.75f);
    EXPECT_EQ(engine->world().resource<systems::OutputCanvas>().canvas_size, glm::ivec2(360, 203));
}

TEST(AdaptiveScale, AMissedTargetDrivesTheScaleBelowOneAndTheCanvasFollows) {
    auto engine = make_engine(make_params({"render.target_fps=240", "render.min_scale=0.5"}), size);
    ASSERT_TRUE(engine);
    auto& adaptive = engine->world().resource<systems::AdaptiveScale>();
    adaptive.timing.hold_s = 0.25;
    float lowest = 1;
    for (int frame = 0; frame < 400 && adaptive.scale > 0.5f; ++frame) {
        ASSERT_TRUE(engine->frame(1.0 / 60).ok());
        lowest = std::min(lowest, adaptive.scale);
        ASSERT_GE(adaptive.scale, 0.5f) << "never below render.min_scale";
    }
    EXPECT_EQ(adaptive.target_fps, 240.0);
    ASSERT_TRUE(adaptive.controller.has_value());
    EXPECT_EQ(adaptive.scale, 0.5f) << "a target no scale meets ends at render.min_scale";
    EXPECT_GT(adaptive.controller->last_cost_s(), 1.1 / 240) << "the measured cost missed the budget";
    ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    EXPECT_EQ(engine->world().resource<systems::OutputCanvas>().canvas_size, glm::ivec2(240, 135));
    // The picture is still the whole screen, scaled up.
    const assets::Image image = engine->read_frame();
    EXPECT_EQ(image.width, size.x);
    EXPECT_GT(luma_stddev(image, 0, 0, size.x, size.y), 3.0);
}

// A target no scale meets: once at render.min_scale, one warning (not one a window) with the figure and
// the settings that would hold it, and the --stats line's marker.
TEST(AdaptiveScale, WhenEvenTheSmallestScaleMissesItSaysSoOnce) {
    LogLines warnings(spdlog::level::warn);
    auto engine = make_engine(make_params({"render.target_fps=240", "render.min_scale=0.5"}), size);
    ASSERT_TRUE(engine);
    auto& adaptive = engine->world().resource<systems::AdaptiveScale>();
    adaptive.timing.hold_s = 0.1;
    int frame = 0;
    for (; frame < 600 && !adaptive.short_at_floor; ++frame) ASSERT_TRUE(engine->frame(1.0 / 60).ok());
    ASSERT_TRUE(adaptive.short_at_floor) << "reached render.min_scale and missed there";
    EXPECT_EQ(adaptive.scale, 0.5f);
    for (int more = 0; more < 60; ++more) ASSERT_TRUE(engine->frame(1.0 / 60).ok());  // several windows more
    EXPECT_EQ(warnings.count("render: even the smallest scale cannot hold 240 fps: at render.min_scale 0.50"),
              1);
    EXPECT_EQ(warnings.count("Set render.target_fps to "), 1);
    EXPECT_EQ(warnings.count("or choose a lighter look"), 1);
}

TEST(AdaptiveScale, AMetTargetKeepsFullScale) {
    auto engine = make_engine(make_params({"render.target_fps=1"}), size);
    ASSERT_TRUE(engine);
    auto& adaptive = engine->world().resource<systems::AdaptiveScale>();
    adaptive.timing.hold_s = 0.1;
    int windows = 0;
    double started = monotonic_seconds();
    for (int frame = 0; frame < 200 && windows < 3; ++frame) {
        ASSERT_TRUE(engine->frame(1.0 / 60).ok());
        EXPECT_EQ(adaptive.scale, 1.0f);
        if (monotonic_seconds() - started > 0.15) {
            started = monotonic_seconds();
            ++windows;
        }
    }
    ASSERT_TRUE(adaptive.controller.has_value());
    EXPECT_GT(adaptive.controller->last_cost_s(), 0.0) << "it measured and decided";
}

}  // namespace
}  // namespace puddle::test
