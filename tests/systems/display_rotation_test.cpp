// display.rotation: the picture on a turned screen is the upright picture turned, pixel for pixel.
#include <gtest/gtest.h>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr int W = 160, H = 90;

assets::Image render(const std::string& rotation, glm::ivec2 size) {
    auto engine = make_engine(make_params({"display.rotation=" + rotation, "rain.seed=5"}), size);
    EXPECT_TRUE(engine);
    return engine ? render_frames(*engine, 30) : assets::Image{};
}

// The upright image turned clockwise by quarter turns, rows top first (as read_pixels gives them).
assets::Image turn(const assets::Image& a, int quarter_turns) {
    const bool swap = quarter_turns % 2 == 1;
    assets::Image b = assets::Image::make(swap ? a.height : a.width, swap ? a.width : a.height);
    for (int r = 0; r < b.height; ++r)
        for (int c = 0; c < b.width; ++c) {
            int sr = r, sc = c;
            if (quarter_turns == 1) sr = a.height - 1 - c, sc = r;
            if (quarter_turns == 2) sr = a.height - 1 - r, sc = a.width - 1 - c;
            if (quarter_turns == 3) sr = c, sc = a.width - 1 - r;
            for (int k = 0; k < 4; ++k)
                b.data[(static_cast<std::size_t>(r) * b.width + c) * 4 + k] =
                    a.data[(static_cast<std::size_t>(sr) * a.width + sc) * 4 + k];
        }
    return b;
}

TEST(DisplayRotation, EachTurnIsTheUprightPictureTurnedClockwise) {
    const assets::Image upright = render("0", {W, H});
    ASSERT_GT(luma_stddev(upright, 0, 0, W, H), 3.0);
    for (int q : {1, 2, 3}) {
        const glm::ivec2 screen = q % 2 ? glm::ivec2(H, W) : glm::ivec2(W, H);
        const assets::Image turned = render(std::to_string(90 * q), screen);
        ASSERT_EQ(turned.width, screen.x);
        ASSERT_EQ(turned.height, screen.y);
        const ImageDiff d = compare_images(turned, turn(upright, q), 0);
        EXPECT_LE(d.max_channel_diff, 1) << 90 * q << " degrees";
        if (q == 2) {
            EXPECT_GT(compare_images(turned, upright, 0).mean_abs_diff, 1.0) << "180 is not a no-op";
        }
    }
}

TEST(DisplayRotation, ChangingItWhileRunningTakesEffectOnTheNextFrame) {
    auto engine = make_engine(make_params({"rain.seed=5"}), {W, H});
    ASSERT_TRUE(engine);
    render_frames(*engine, 29);
    engine->params().set(params::ParamId::display_rotation, std::string("180"), params::ParamSource::CommandLine);
    const assets::Image turned = render_frames(*engine, 1);
    const assets::Image upright = render("0", {W, H});
    EXPECT_LE(compare_images(turned, turn(upright, 2), 0).max_channel_diff, 1);
}

}  // namespace
}  // namespace puddle::test
