// Analytic ripples (REFERENCE.md section 4): the closed form on the GPU equals the formula on the CPU,
// the sources stay alive in the number asked for, and a ring travels at the speed the wave field's rings
// do for the same parameters (the analytic model as an exact reference for the wave field).
#include "systems/analytic_ripples/analytic_ripple_system.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu_fixture.hpp"
#include "systems/wave_test_support.hpp"

namespace puddle::test {
namespace {

using systems::AnalyticRipples;
using systems::AnalyticSource;

constexpr int N = 128;
constexpr float C = 64.5f;  // the centre of texel 64, as in the wave tests

std::unique_ptr<app::Engine> analytic_engine() {
    return make_engine(make_params({"wave.resolution=" + std::to_string(N), "drops.model=analytic"}),
                       {32, 18});
}

// The surface's height channel, rows by y, as a Field (previous heights unused).
Field read_surface_heights(app::Engine& e) {
    const auto& surface = e.world().resource<systems::Surface>();
    const std::vector<float> texels = e.device().read_texture(surface.texture);
    Field f{surface.resolution, std::vector<float>(texels.size() / 2)};
    for (std::size_t i = 0; i < texels.size() / 4; ++i)  // decoded as surface_encoding.glsl does
        f.hv[2 * i] = surface.unorm ? (texels[4 * i] * 255.0f - 128.0f) / 127.0f * 4.0f : texels[4 * i];
    return f;
}

Field draw_sources(app::Engine& e, std::initializer_list<AnalyticSource> sources) {
    auto& ripples = e.world().resource<AnalyticRipples>();
    ripples.count = 0;
    for (const AnalyticSource& s : sources) set_analytic_source(ripples, ripples.count++, s);
    systems::analytic_ripple_pass(e.device(), ripples, e.world().resource<systems::Surface>());
    return read_surface_heights(e);
}

AnalyticSource one_ring(float age) {
    return {.position = {C, C},
            .age = age,
            .amplitude = 1.0f,
            .spatial_decay = 1e-4f,
            .temporal_decay = 0,
            .frequency_decay = 0,
            .angular_frequency = 30.0f,
            .speed = 60.0f / std::sqrt(2.0f),
            .max_phase = 3.14159265f};  // half a ring: one crest, whose peak moves at v
}

TEST(AnalyticRipples, GpuSumEqualsTheClosedForm) {
    auto e = analytic_engine();
    ASSERT_TRUE(e);
    const AnalyticSource a{.position = {40.5f, 50.5f},
                           .age = 0.9f,
                           .amplitude = 0.7f,
                           .spatial_decay = 1e-3f,
                           .temporal_decay = 0.5f,
                           .frequency_decay = 0.3f,
                           .angular_frequency = 25.0f,
                           .speed = 40.0f,
                           .max_phase = 4 * 6.2831853f};
    const AnalyticSource b{.position = {90.5f, 70.5f},
                           .age = 0.5f,
                           .amplitude = 0.4f,
                           .spatial_decay = 0,
                           .temporal_decay = 1.0f,
                           .frequency_decay = 0,
                           .angular_frequency = 40.0f,
                           .speed = 60.0f,
                           .max_phase = 2 * 6.2831853f};
    const Field f = draw_sources(*e, {a, b});
    double worst = 0, peak = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            const double expected = systems::analytic_height(a, std::hypot(x + 0.5 - 40.5, y + 0.5 - 50.5)) +
                                    systems::analytic_height(b, std::hypot(x + 0.5 - 90.5, y + 0.5 - 70.5));
            peak = std::max(peak, std::abs(expected));
            worst = std::max(worst, std::abs(f.cur(x, y) - expected));
        }
    EXPECT_GT(peak, 0.1);
    EXPECT_LT(worst, 2e-3) << "half-float surface: about 3 significant digits";
}

// The slopes come from the derivative in closed form: they must equal -2 dh/dx, -2 dh/dy of the formula
// (what surface.frag's one-texel central differences approximate), away from the front's kink.
TEST(AnalyticRipples, SlopesAreTheFormulasDerivative) {
    auto e = analytic_engine();
    ASSERT_TRUE(e);
    AnalyticSource s = one_ring(0.7f);
    s.max_phase = 1000.0f;  // no cut-off ring: the height is smooth behind the front
    draw_sources(*e, {s});
    const auto& surface = e->world().resource<systems::Surface>();
    ASSERT_FALSE(surface.unorm) << "llvmpipe renders half floats";
    const std::vector<float> t = e->device().read_texture(surface.texture);
    auto h = [&](double x, double y) { return systems::analytic_height(s, std::hypot(x - C, y - C)); };
    const double eps = 1e-3, front = double(s.speed) * double(s.age);
    double worst = 0, peak = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            if (std::hypot(px - C, py - C) > front - 1.0) continue;
            const double sx = -(h(px + eps, py) - h(px - eps, py)) / eps;  // -2 dh/dx
            const double sy = -(h(px, py + eps) - h(px, py - eps)) / eps;
            const std::size_t i = (std::size_t(y) * N + x) * 4;
            peak = std::max(peak, std::abs(sx));
            worst = std::max({worst, std::abs(t[i + 1] - sx), std::abs(t[i + 2] - sy)});
        }
    EXPECT_GT(peak, 0.5);
    EXPECT_LT(worst, 0.01 * peak);
}

TEST(AnalyticRipples, KeepsTheAskedNumberOfSourcesAlive) {
    const params::Params p = make_params({"analytic.sources=500", "analytic.lifetime=3"});
    for (double now : {0.0, 1.234, 1000.5, 3.0e6}) {
        int newborn = 0;
        for (int i = 0; i < 500; ++i) {
            const AnalyticSource s = systems::sample_analytic_source(p, i, 500, now, 512);
            ASSERT_GE(s.age, 0.0f);
            ASSERT_LT(s.age, 3.0f + 1e-3f);
            ASSERT_GE(s.position.x, 0.0f);
            ASSERT_LT(s.position.x, 512.0f);
            if (s.age < 0.3f) ++newborn;
        }
        // Births are spread evenly over the lifetime: a tenth of it holds a tenth of the sources.
        EXPECT_NEAR(newborn, 50, 2) << "at " << now;
    }
}

// The reference wave field's ring and the analytic ring, both at the wave field's scheme speed
// (steps_per_second / sqrt 2 texels per second). Tolerance: 10% for the wave field, whose ring disperses
// (short waves lag); 4% for the analytic ring, whose only error is the one-texel binning of the peak radius.
TEST(AnalyticRipples, RingTravelsAtTheWaveFieldsSpeed) {
    const double steps_per_second = 60.0, v = steps_per_second / std::sqrt(2.0);

    auto wave = make_engine(make_params({"wave.resolution=" + std::to_string(N), "wave.model=reference",
                                         "wave.damping=1", "rain.intensity=0"}),
                            {32, 18});
    ASSERT_TRUE(wave);
    step(*wave, {{C, C, 1.0f}});
    for (int i = 1; i < 20; ++i) step(*wave);
    const double wave_r20 = peak_radius(read_field(*wave), C, C);
    for (int i = 20; i < 60; ++i) step(*wave);
    const double wave_r60 = peak_radius(read_field(*wave), C, C);
    const double wave_speed = (wave_r60 - wave_r20) / (40.0 / steps_per_second);

    auto e = analytic_engine();
    ASSERT_TRUE(e);
    const double r20 = peak_radius(draw_sources(*e, {one_ring(20.0f / 60.0f)}), C, C);
    const double r60 = peak_radius(draw_sources(*e, {one_ring(60.0f / 60.0f)}), C, C);
    const double analytic_speed = (r60 - r20) / (40.0 / steps_per_second);

    EXPECT_NEAR(analytic_speed, v, 0.04 * v) << "r20 " << r20 << " r60 " << r60;
    EXPECT_NEAR(wave_speed, analytic_speed, 0.10 * analytic_speed)
        << "wave r20 " << wave_r20 << " r60 " << wave_r60;
}

}  // namespace
}  // namespace puddle::test
