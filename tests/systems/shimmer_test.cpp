// A still scene does not shimmer. The puddle reads its surface through the surface's mip chain
// (trilinear, by each pixel's footprint: systems/water/surface_system.cpp), so thin rings far away are
// averaged instead of sampled, and nothing else in the default look moves on its own: once the rain has
// stopped and its rings have died out, consecutive frames are the same picture. While it rains they are
// not, so the comparison does see motion.
#include <gtest/gtest.h>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

using params::ParamId;

TEST(Shimmer, AStillSceneIsTheSamePictureFrameAfterFrame) {
    auto engine = make_engine(make_params({"rain.seed=3"}), {320, 180});
    ASSERT_TRUE(engine);
    render_frames(*engine, 60);  // a second of the default rain
    const assets::Image raining_a = render_frames(*engine, 1);
    const assets::Image raining_b = render_frames(*engine, 1);
    EXPECT_GT(compare_images(raining_a, raining_b, 4).fraction_over, 0.01) << "the rain moves the water";

    engine->params().set(ParamId::rain_rate, 0.0f, params::ParamSource::CommandLine);
    render_frames(*engine, 240);  // four seconds: the capillary rings are gone within about one
    const assets::Image still_a = render_frames(*engine, 1);
    const assets::Image still_b = render_frames(*engine, 1);
    const ImageDiff d = compare_images(still_a, still_b, 2);
    EXPECT_LT(d.fraction_over, 0.001) << "pixels changing by more than 2 of 255 between still frames";
    EXPECT_LT(d.mean_abs_diff, 0.05);
    EXPECT_LE(d.max_channel_diff, 8);
}

}  // namespace
}  // namespace puddle::test
