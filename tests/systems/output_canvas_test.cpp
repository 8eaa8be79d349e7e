// display.rotation: the picture on a turned screen is the upright picture turned, pixel for pixel.
// render.scale: the picture at half scale is the half-size picture scaled up bilinearly.
// display.brightness: the last pass multiplies each (display-encoded) 8-bit value, turned or not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"

namespace puddle::test {
namespace {

constexpr int W = 160, H = 90;

assets::Image render(const std::string& rotation, glm::ivec2 size, const std::string& scale = "1",
                     const std::string& brightness = "1") {
    auto engine =
        make_engine(make_params({"display.rotation=" + rotation, "rain.seed=5", "overlay.rain=false",
                                 "render.scale=" + scale, "display.brightness=" + brightness}),
                    size);
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
    auto engine = make_engine(make_params({"rain.seed=5", "overlay.rain=false"}), {W, H});
    ASSERT_TRUE(engine);
    render_frames(*engine, 29);
    engine->params().set(params::ParamId::display_rotation, std::string("180"),
                         params::ParamSource::CommandLine);
    const assets::Image turned = render_frames(*engine, 1);
    const assets::Image upright = render("0", {W, H});
    EXPECT_LE(compare_images(turned, turn(upright, 2), 0).max_channel_diff, 1);
}

// Bilinear scaling by 2, texel centres on texel centres, edges clamped: what a GPU's linear filter does.
assets::Image double_size(const assets::Image& a) {
    assets::Image b = assets::Image::make(a.width * 2, a.height * 2);
    for (int r = 0; r < b.height; ++r)
        for (int c = 0; c < b.width; ++c) {
            const float x = std::clamp((c + 0.5f) / 2.0f - 0.5f, 0.0f, float(a.width - 1));
            const float y = std::clamp((r + 0.5f) / 2.0f - 0.5f, 0.0f, float(a.height - 1));
            const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, a.width - 1),
                      y1 = std::min(y0 + 1, a.height - 1);
            const float fx = x - float(x0), fy = y - float(y0);
            for (int k = 0; k < 4; ++k) {
                const auto at = [&](int xx, int yy) {
                    return float(a.data[(static_cast<std::size_t>(yy) * a.width + xx) * 4 + k]);
                };
                const float top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
                const float bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
                b.data[(static_cast<std::size_t>(r) * b.width + c) * 4 + k] =
                    static_cast<std::uint8_t>(std::lround(top + (bottom - top) * fy));
            }
        }
    return b;
}

TEST(RenderScale, HalfScaleIsTheHalfSizePictureScaledUp) {
    const assets::Image small = render("0", {W, H});
    const assets::Image scaled = render("0", {2 * W, 2 * H}, "0.5");
    ASSERT_EQ(scaled.width, 2 * W);
    ASSERT_EQ(scaled.height, 2 * H);
    const ImageDiff d = compare_images(scaled, double_size(small), 2);
    EXPECT_LE(d.max_channel_diff, 2);
    EXPECT_LT(d.mean_abs_diff, 0.2);
    // The comparison sees detail: the full-scale picture has some the scaled one cannot.
    EXPECT_GT(compare_images(render("0", {2 * W, 2 * H}), scaled, 8).fraction_over, 0.01);
}

TEST(RenderScale, TurnsAndScalesTogether) {
    const assets::Image scaled = render("0", {2 * W, 2 * H}, "0.5");
    const assets::Image turned = render("180", {2 * W, 2 * H}, "0.5");
    EXPECT_LE(compare_images(turned, turn(scaled, 2), 0).max_channel_diff, 1);
    const assets::Image portrait = render("90", {2 * H, 2 * W}, "0.5");
    ASSERT_EQ(portrait.width, 2 * H);
    EXPECT_LE(compare_images(portrait, turn(scaled, 1), 1).mean_abs_diff, 0.05);
}

TEST(DisplayBrightness, HalfHalvesEveryPixelValueTurnedOrNot) {
    for (const char* rotation : {"0", "90"}) {
        const glm::ivec2 screen = std::string(rotation) == "0" ? glm::ivec2(W, H) : glm::ivec2(H, W);
        const assets::Image full = render(rotation, screen);
        const assets::Image half = render(rotation, screen, "1", "0.5");
        ASSERT_EQ(half.data.size(), full.data.size());
        ASSERT_GT(luma_stddev(full, 0, 0, screen.x, screen.y), 3.0);
        int worst = 0, brightest = 0;
        for (std::size_t i = 0; i < full.data.size(); ++i) {
            if (i % 4 == 3) continue;  // alpha stays
            brightest = std::max(brightest, static_cast<int>(full.data[i]));
            worst = std::max(worst,
                             std::abs(2 * static_cast<int>(half.data[i]) - static_cast<int>(full.data[i])));
        }
        EXPECT_GT(brightest, 40) << rotation;
        EXPECT_LE(worst, 1) << rotation << ": each 8-bit value halved, to the rounding of the last bit";
    }
}

}  // namespace
}  // namespace puddle::test
