// GpuTimer (gpu/gpu_timer.hpp) on a real context: with timer queries (llvmpipe has them) it gives the time
// of the work between begin and end, later and without waiting; without them it measures nothing.
#include "gpu/gpu_timer.hpp"

#include <gtest/gtest.h>

#include <optional>

#include "gpu/device.hpp"
#include "support/gpu_fixture.hpp"

namespace puddle::gpu {
namespace {

class GpuTimerTest : public test::DeviceFixture {};

TEST_F(GpuTimerTest, TimesTheDrawsBetweenBeginAndEnd) {
    GpuTimer timer = device_->create_gpu_timer();
    EXPECT_EQ(timer.supported(), device_->caps().timer_queries);
    if (!timer.supported()) {
        timer.begin();
        timer.end();
        device_->finish();
        EXPECT_FALSE(timer.read().has_value());
        GTEST_SKIP() << "no GL_EXT_disjoint_timer_query on " << device_->caps().renderer;
    }
    EXPECT_FALSE(timer.read().has_value()) << "nothing timed yet";
    const Texture target = test::make_target(*device_, {256, 256}, {0, 0, 0, 1});
    const Texture source = test::make_target(*device_, {256, 256}, {0.5f, 0.5f, 0.5f, 1});
    const Pipeline copy = test::make_copy_pipeline(*device_, Blend::Alpha);
    timer.begin();
    for (int k = 0; k < 20; ++k) test::draw_texture(*device_, target, copy, source);
    timer.end();
    device_->finish();
    std::optional<double> seconds;
    for (int tries = 0; tries < 100 && !seconds; ++tries) seconds = timer.read();  // finish() made it ready
    ASSERT_TRUE(seconds.has_value());
    EXPECT_GT(*seconds, 0.0);
    EXPECT_LT(*seconds, 10.0);
    EXPECT_FALSE(timer.read().has_value()) << "each span is read once";
}

TEST_F(GpuTimerTest, ASpanIsSkippedWhileEveryQueryWaits) {
    GpuTimer timer = device_->create_gpu_timer();
    if (!timer.supported()) GTEST_SKIP() << "no GL_EXT_disjoint_timer_query on " << device_->caps().renderer;
    for (int k = 0; k < GpuTimer::depth + 2; ++k) {  // none read: the last two find the ring full
        timer.begin();
        timer.end();
    }
    device_->finish();
    int read = 0;
    for (int tries = 0; tries < 100; ++tries) read += timer.read().has_value() ? 1 : 0;
    EXPECT_EQ(read, GpuTimer::depth);
}

}  // namespace
}  // namespace puddle::gpu
