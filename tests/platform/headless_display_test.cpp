// The headless backend: surfaceless EGL, an offscreen target of the requested size.
#include <gtest/gtest.h>

#include "gpu/device.hpp"
#include "platform/display.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::platform {
namespace {

TEST(HeadlessDisplay, OffscreenTargetHasTheRequestedSize) {
    auto d = create_headless_display({.backend = BackendKind::Headless, .size = {100, 50}});
    ASSERT_TRUE(d.ok()) << d.error().message;
    gpu::Device device;
    ASSERT_TRUE((*d)->prepare(device).ok());
    const gpu::FrameTarget t = (*d)->frame_target();
    ASSERT_NE(t.texture, nullptr);
    EXPECT_EQ(t.size, glm::ivec2(100, 50));
    EXPECT_EQ(t.texture->width(), 100);
    EXPECT_EQ((*d)->kind(), BackendKind::Headless);
    EXPECT_NE((*d)->describe().find("surfaceless"), std::string::npos);
    EXPECT_TRUE((*d)->present().ok());
}

// What differs from a screen, as callers ask it: nobody sees the frames, and there is no output to
// switch off or console to take over.
TEST(HeadlessDisplay, SaysItShowsNoFramesAndSwitchesNoOutput) {
    auto d = create_headless_display({.backend = BackendKind::Headless, .size = {16, 16}});
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_FALSE((*d)->shows_frames());
    EXPECT_FALSE((*d)->switches_output_power());
    EXPECT_FALSE((*d)->owns_the_console());
}

TEST(HeadlessDisplay, DefaultSizeIs640x360) {
    auto d = create_headless_display({.backend = BackendKind::Headless});
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ((*d)->size(), glm::ivec2(640, 360));
}

// Engines share one EGLDisplay per process; ending one must not terminate the display under another.
TEST(HeadlessDisplay, EndingOneEngineLeavesAnotherWorking) {
    const params::Params params;
    auto survivor = test::make_engine(params, {96, 54});
    ASSERT_TRUE(survivor);
    {
        auto other = test::make_engine(params, {96, 54});
        ASSERT_TRUE(other);
    }
    const assets::Image after = test::render_frames(*survivor, 20);
    auto fresh = test::make_engine(params, {96, 54});
    ASSERT_TRUE(fresh);
    const assets::Image expected = test::render_frames(*fresh, 20);
    EXPECT_LE(test::compare_images(after, expected, 0).max_channel_diff, 1);
    EXPECT_GT(test::luma_stddev(after, 0, 0, 96, 54), 3.0) << "a picture, not a flat fill";
}

}  // namespace
}  // namespace puddle::platform
