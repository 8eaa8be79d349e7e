// Colour end to end: sRGB textures decode to linear in the sampler, HDR stays linear, the output is
// encoded once (a mid-grey goes through unchanged); exposure scales radiance by powers of two before
// tone mapping; the tone-mapping operators do what look.tonemap documents; HDR lights stay bright.
#include <gtest/gtest.h>

#include <cmath>

#include "assets/image_io.hpp"
#include "support/test_support.hpp"
#include "systems/environment_test_support.hpp"
#include "systems/render_test_support.hpp"
#include "systems/sky/environment_system.hpp"

namespace puddle::test {
namespace {

// Looking level from high above the puddle: every pixel is sky; no vignette and no falling rain, so every
// pixel is the same. In the box: the ground beside a shore reaches the horizon.
const std::initializer_list<std::string> kSkyOnly{"camera.position=0,100,0", "camera.target=0,100,-10",
                                                  "look.vignette=0",         "rain.intensity=0",
                                                  "overlay.rain=false",      "puddle.shape=box"};

assets::Image render_sky(const std::string& env, std::initializer_list<std::string> more = {}) {
    params::Params p = make_params(kSkyOnly);
    apply_sets(p, more);
    apply_sets(p, {"environment.image=" + env});
    auto engine = make_engine(p, {64, 36});
    if (!engine) return {};
    return render_frames(*engine, 2);
}

// Every channel of every pixel, as min and max.
std::pair<int, int> channel_range(const assets::Image& img) {
    int lo = 255, hi = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c)
                lo = std::min<int>(lo, img.pixel8(x, y)[c]), hi = std::max<int>(hi, img.pixel8(x, y)[c]);
    return {lo, hi};
}

std::string uniform_exr(const TempDir& dir, const std::string& name, float value) {
    const std::string path = (dir / name).string();
    write_float_image(path, panorama_of(64, [value](glm::vec3) { return glm::vec3(value); }));
    return path;
}

TEST(Colour, MidGreySrgbComesOutAsTheSameMidGrey) {
    TempDir dir;
    assets::Image grey = assets::Image::make(8, 8);
    std::fill(grey.data.begin(), grey.data.end(), std::uint8_t{128});
    for (const char* f : assets::cube_face_names)
        ASSERT_TRUE(assets::write_png((dir / (std::string(f) + ".png")).string(), grey).ok());
    for (const char* op : {"clip", "soft"}) {
        const auto img = render_sky(dir.path().string(), {std::string("look.tonemap=") + op});
        ASSERT_FALSE(img.empty());
        EXPECT_EQ(channel_range(img), std::make_pair(128, 128)) << "tonemap " << op;
    }
    // The same grey as an 8-bit panorama: through the GPU's conversion into an sRGB cube and back.
    assets::Image panorama = assets::Image::make(64, 32);
    std::fill(panorama.data.begin(), panorama.data.end(), std::uint8_t{128});
    const std::string png = (dir / "grey_panorama.png").string();
    ASSERT_TRUE(assets::write_png(png, panorama).ok());
    EXPECT_EQ(channel_range(render_sky(png, {"look.tonemap=clip"})), std::make_pair(128, 128));
    // The same grey as linear HDR radiance (sRGB 128 is 0.21586 linear) comes out the same.
    const auto hdr = render_sky(uniform_exr(dir, "grey.exr", 0.21586f), {"look.tonemap=clip"});
    EXPECT_EQ(channel_range(hdr), std::make_pair(128, 128));
}

TEST(Colour, ExposureDoublesAndHalvesRadianceBeforeToneMapping) {
    TempDir dir;
    const std::string sky = uniform_exr(dir, "sky.exr", 0.2f);
    for (bool fallback : {false, true}) {
        auto radiance = [&](const char* stops) {
            params::Params p = make_params(kSkyOnly);
            apply_sets(p, {"environment.image=" + sky, std::string("environment.exposure=") + stops,
                           "look.tonemap=clip"});
            auto engine = make_engine(p, {64, 36}, {.forbid_float_targets = fallback});
            return engine ? srgb_to_linear(render_frames(*engine, 2).pixel8(32, 18)[1]) : 0.0f;
        };
        const float base = radiance("0"), up = radiance("1"), down = radiance("-1");
        EXPECT_NEAR(base, 0.2f, 0.004f) << (fallback ? "rgbm" : "half float");
        EXPECT_NEAR(up / base, 2.0f, 0.05f) << (fallback ? "rgbm" : "half float");
        EXPECT_NEAR(down / base, 0.5f, 0.0125f) << (fallback ? "rgbm" : "half float");
    }
}

TEST(Colour, HdrCrossIsLinearInHalfFloatAndInForcedRgbm) {
    // Six faces uploaded from the CPU (a cross), not made by the panorama pass: same radiance either way.
    TempDir dir;
    const std::string cross = (dir / "cross.exr").string();
    assets::Image img = assets::Image::make(64, 48, assets::PixelFormat::RGBA32F);
    for (std::size_t i = 0; i < img.data.size() / sizeof(float); ++i)
        img.pixelf(0, 0)[i] = (i % 4 == 3) ? 1.0f : 0.2f;
    write_float_image(cross, img);
    for (bool fallback : {false, true}) {
        params::Params p = make_params(kSkyOnly);
        apply_sets(p, {"environment.image=" + cross, "look.tonemap=clip"});
        auto engine = make_engine(p, {64, 36}, {.forbid_float_targets = fallback});
        ASSERT_TRUE(engine);
        EXPECT_EQ(engine->world().resource<systems::Environment>().rgbm, fallback);
        EXPECT_NEAR(srgb_to_linear(render_frames(*engine, 2).pixel8(32, 18)[0]), 0.2f, 0.004f)
            << (fallback ? "rgbm" : "half float");
    }
}

TEST(Colour, ToneMappingOperatorsFollowTheirFormulas) {
    TempDir dir;
    const std::string one = uniform_exr(dir, "one.exr", 1.0f), half = uniform_exr(dir, "half.exr", 0.5f);
    auto out = [&](const std::string& env, const char* op) {
        const auto img = render_sky(env, {std::string("look.tonemap=") + op});
        return img.empty() ? -1 : int(img.pixel8(10, 10)[0]);
    };
    auto srgb = [](double linear) {
        return int(std::lround(
            255.0 * (linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055)));
    };
    EXPECT_EQ(out(one, "clip"), 255);
    EXPECT_NEAR(out(one, "soft"), srgb(0.8 + 0.2 * (1 - std::exp(-1.0))), 1);  // the shoulder past 0.8
    EXPECT_NEAR(out(one, "reinhard"), srgb(0.5), 1);
    EXPECT_NEAR(out(one, "aces"), srgb(2.54 / 3.16), 1);
    EXPECT_NEAR(out(half, "soft"), srgb(0.5), 1) << "below the knee soft changes nothing";
    EXPECT_NEAR(out(half, "clip"), srgb(0.5), 1);
    EXPECT_NEAR(out(half, "reinhard"), srgb(1.0 / 3.0), 1);
}

TEST(Colour, HdrLightsStayBrightInTheReflection) {
    // The same bright sky as HDR radiance 6 and as an 8-bit picture (white: 1). Reflected at 30% to 80%,
    // the 8-bit one gives grey water; the HDR one stays near white.
    TempDir dir;
    const std::string hdr = uniform_exr(dir, "bright.exr", 6.0f);
    assets::Image white = assets::Image::make(64, 32);
    std::fill(white.data.begin(), white.data.end(), std::uint8_t{255});
    const std::string ldr = (dir / "white.png").string();
    ASSERT_TRUE(assets::write_png(ldr, white).ok());
    const auto bright = render_with({"environment.image=" + hdr, "rain.intensity=0"}, 3);
    const auto clipped = render_with({"environment.image=" + ldr, "rain.intensity=0"}, 3);
    const double hdr_water = mean_luma(bright, 40, 50, 120, 85),
                 ldr_water = mean_luma(clipped, 40, 50, 120, 85);
    EXPECT_GT(hdr_water, 220.0);
    EXPECT_LT(ldr_water, 190.0);
}

}  // namespace
}  // namespace puddle::test
