// Screens of a wall in step: two headless engines on the realtime
// clock (injected, so the test runs in milliseconds of wall time), started seconds apart and framing at
// different moments of the 60 Hz period, show the same height field and the same frame at the same wall
// time once the later one has warmed up; a clock step back on one of them re-syncs it to the same picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "support/gpu_fixture.hpp"
#include "support/test_support.hpp"
#include "systems/clock/wall_clock.hpp"
#include "systems/clock/wall_steps.hpp"
#include "systems/water/wave_system.hpp"

namespace puddle::test {
namespace {

using systems::ns_per_second;

constexpr std::int64_t start_ns = 1'764'590'400LL * ns_per_second;  // 2025-12-01 12:00:00 UTC
constexpr std::int64_t frame_ns = 16'666'667;                       // 60 Hz
constexpr glm::ivec2 tile_size{160, 90};

// Residual allowed between the screens' height fields, relative to the field's largest height. The
// warm-up leaves damping^(steps/2) = 1.1e-4 of the difference at the start (systems/clock/wall_clock.hpp),
// times at most 1/sin(acos(sqrt(damping))) = 8.2 for the slowest mode: 9.5e-4. Measured: printed by the test.
constexpr double height_tolerance = 1e-3;
// Pixels: where a residual of 1e-4 meets a steep highlight a channel may move by a few levels of 255 (up to
// 10 measured), so the frames must agree far inside the golden images' tolerance (mean 1.5, 1% of pixels
// off by over 32): mean under 0.05, at most 0.5% of pixels off by more than 2, none by more than 16.
constexpr int pixel_threshold = 2;
constexpr double pixel_mean_tolerance = 0.05;
constexpr double pixel_fraction_tolerance = 0.005;
constexpr int pixel_max_tolerance = 16;

struct Tile {
    std::unique_ptr<app::Engine> engine;
    std::int64_t now = 0;     // the true wall time
    std::int64_t offset = 0;  // how wrong this screen's clock is: it reads now + offset

    Tile(std::int64_t start, std::vector<std::string> sets) : now(start) {
        params::Params p = make_params({"wave.resolution=128", "rain.seed=11", "wall.clock=realtime"});
        apply_sets(p, sets);
        engine = make_engine(p, tile_size);
        if (engine) engine->world().resource<systems::WallClock>().now_ns = [this] { return now + offset; };
    }
    void frame() { ASSERT_TRUE(engine->frame(1.0 / 60.0).ok()); }
    // Frames at 60 Hz from its own `now` until its clock has no steps left to catch up.
    void run_until_in_step(int limit = 60) {
        for (int n = 0; n < limit; ++n) {
            frame();
            now += frame_ns;
            if (in_step()) return;
        }
        FAIL() << "not in step after " << limit << " frames";
    }
    // Frames at 60 Hz up to (not including) wall time `until`.
    void run_until(std::int64_t until) {
        for (; now < until; now += frame_ns) frame();
    }
    bool in_step() {
        auto& w = engine->world();
        return static_cast<std::int64_t>(w.resource<systems::FrameClock>().step_index) ==
               w.resource<systems::WallSteps>().target_step;
    }
    std::uint64_t step() { return engine->world().resource<systems::FrameClock>().step_index; }
    std::vector<float> heights() {
        engine->make_current();
        return engine->world().resource<systems::WaveField>().read_heights(engine->device());
    }
};

struct Residual {
    double heights = 0;  // max |a - b| / max |a| over the current heights
    ImageDiff pixels;
};

// Both tiles' frame at wall time `at`, compared.
Residual compare_at(Tile& a, Tile& b, std::int64_t at) {
    Residual r;
    a.now = at, b.now = at;
    a.frame(), b.frame();
    EXPECT_EQ(a.step(), b.step());
    const std::vector<float> ha = a.heights(), hb = b.heights();
    double largest = 0, diff = 0;
    for (std::size_t i = 0; i < ha.size(); i += 2) {
        largest = std::max(largest, static_cast<double>(std::abs(ha[i])));
        diff = std::max(diff, static_cast<double>(std::abs(ha[i] - hb[i])));
    }
    EXPECT_GT(largest, 0.01) << "the field must hold ripples for the comparison to mean anything";
    r.heights = diff / largest;
    r.pixels = compare_images(a.engine->read_frame(), b.engine->read_frame(), pixel_threshold);
    return r;
}

void report(const char* what, const Residual& r) {
    std::printf("%s: height residual %.2e; pixels: mean %.4f, %.3f%% off by more than %d, max %d\n", what,
                r.heights, r.pixels.mean_abs_diff, 100 * r.pixels.fraction_over, pixel_threshold,
                r.pixels.max_channel_diff);
}

void expect_same_picture(const Residual& r) {
    EXPECT_LE(r.heights, height_tolerance);
    EXPECT_LE(r.pixels.mean_abs_diff, pixel_mean_tolerance);
    EXPECT_LE(r.pixels.fraction_over, pixel_fraction_tolerance);
    EXPECT_LE(r.pixels.max_channel_diff, pixel_max_tolerance);
}

// b starts 2.5 s after a, framing 7 ms into a's period; after b's warm-up both show the same step, field
// and frame at the same wall time. A second screen with a 1 s warm-up shows that the comparison sees a
// warm-up too short: the capillary field forgets fast (wave.drag), yet what is left of its start after
// 1 s is still some 40 times the tolerance.
TEST(WallInStep, ScreensStartedSecondsApartShowTheSameFrameAfterWarmUp) {
    Tile a(start_ns + 3'000'000, {});
    ASSERT_TRUE(a.engine);
    a.run_until_in_step();
    a.run_until(start_ns + 2'500'000'000);
    Tile b(start_ns + 2'507'000'000, {});
    Tile short_warmup(start_ns + 2'507'000'000, {"wall.warmup=1"});
    ASSERT_TRUE(b.engine && short_warmup.engine);
    b.run_until_in_step();
    short_warmup.run_until_in_step();
    const std::int64_t at = std::max(b.now, a.now) + 30 * frame_ns;
    a.run_until(at), b.run_until(at), short_warmup.run_until(at);

    const Residual r = compare_at(a, b, at);
    const Residual control = compare_at(a, short_warmup, at);
    report("in step", r);
    report("with a 1 s warm-up (control)", control);
    expect_same_picture(r);
    EXPECT_GT(control.heights, 10 * height_tolerance);
    EXPECT_GT(control.pixels.mean_abs_diff, 10 * pixel_mean_tolerance);
}

// One screen's clock is wrong (2 s ahead; 10 minutes behind) until NTP steps it right: it re-syncs in a
// bounded number of frames, no frame simulating more than wall.catch_up_steps, and then shows the same
// picture as the screen whose clock was right all along.
TEST(WallInStep, AScreenWhoseClockIsSteppedRightReSyncsToTheSamePicture) {
    Tile b(start_ns + 5'000'000, {});
    ASSERT_TRUE(b.engine);
    b.run_until_in_step();
    for (const std::int64_t wrong_by : {2 * ns_per_second, -600 * ns_per_second}) {
        Tile a(b.now, {});
        ASSERT_TRUE(a.engine);
        a.offset = wrong_by;
        a.run_until_in_step();
        a.run_until(a.now + 60 * frame_ns);
        a.offset = 0;  // the clock step
        a.frame();
        const auto& clock = a.engine->world().resource<systems::FrameClock>();
        EXPECT_LE(clock.steps_due, a.engine->params().get<params::ParamId::wall_catch_up_steps>());
        EXPECT_EQ(a.engine->world().resource<systems::WallSteps>().resyncs, 2u);  // joining, then the step
        a.now += frame_ns;
        a.run_until_in_step(25);  // 1200 steps at 60 a frame: 21 frames
        const std::int64_t at = std::max(a.now, b.now) + 10 * frame_ns;
        a.run_until(at), b.run_until(at);
        const Residual r = compare_at(a, b, at);
        report(wrong_by > 0 ? "after a clock step of -2 s" : "after a clock step of +600 s", r);
        expect_same_picture(r);
    }
}

}  // namespace
}  // namespace puddle::test
