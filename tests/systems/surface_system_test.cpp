// The surface pass (systems/water/surface_system.hpp): each surface texel holds the field's height there and
// its central differences one texel apart (hL - hR, hD - hU), clamped at the edges (the reference's field) or
// wrapped around them (a capillary field, which repeats), as surface.frag says and the render pass relies on.
// Checked texel by texel against the field read back from the GPU.
#include "systems/water/surface_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/gpu_fixture.hpp"
#include "systems/wave_test_support.hpp"

namespace puddle::test {
namespace {

constexpr int N = 64;

struct SurfaceTexel {
    float height, dx, dz;
    float splash;  // alpha: the splashes of drops that hit in the last 60 ms
};

std::vector<SurfaceTexel> read_surface(app::Engine& e) {
    const auto& surface = e.world().resource<systems::Surface>();
    const std::vector<float> t = e.device().read_texture(surface.texture);
    auto decode = [&](float v) { return surface.unorm ? (v * 255.0f - 128.0f) / 127.0f * 4.0f : v; };
    std::vector<SurfaceTexel> out(t.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {decode(t[4 * i]), decode(t[4 * i + 1]), decode(t[4 * i + 2]), t[4 * i + 3]};
    return out;
}

// Compares every surface texel with the field read back; `periodic`: differences wrap around the edges.
void expect_surface_matches_field(app::Engine& e, bool periodic) {
    auto& w = e.world();
    systems::surface_system(e.device(), w.resource<systems::WaveField>(), w.resource<systems::Surface>());
    const Field f = read_field(e);
    const std::vector<SurfaceTexel> s = read_surface(e);
    ASSERT_EQ(s.size(), std::size_t(N) * N);
    const bool unorm = w.resource<systems::Surface>().unorm;
    const double tolerance = unorm ? 8.0 / 254.0 : 2e-3;  // a byte step of [-4, 4], or half-float rounding
    auto edge = [&](int i) { return periodic ? (i + N) % N : std::clamp(i, 0, N - 1); };
    auto h = [&](int x, int y) { return f.cur(edge(x), edge(y)); };
    double peak = 0, worst = 0, edge_peak = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            const SurfaceTexel& t = s[std::size_t(y) * N + x];
            peak = std::max(peak, std::abs(h(x, y)));
            if (x == 0 || y == 0 || x == N - 1 || y == N - 1)
                edge_peak = std::max(edge_peak, std::abs(h(x, y)));
            worst =
                std::max({worst, std::abs(t.height - h(x, y)), std::abs(t.dx - (h(x - 1, y) - h(x + 1, y))),
                          std::abs(t.dz - (h(x, y - 1) - h(x, y + 1)))});
        }
    ASSERT_GT(peak, 0.01) << "the drops made waves";
    ASSERT_GT(edge_peak, 0.1 * peak) << "waves at the edges, where clamping and wrapping differ";
    EXPECT_LT(worst, tolerance * std::max(1.0, peak));
}

TEST(SurfaceSystem, HoldsTheHeightAndItsCentralDifferencesClampedAtTheEdges) {
    auto e = make_engine(
        make_params({"wave.model=reference", "wave.resolution=" + std::to_string(N), "rain.intensity=0"}),
        {32, 18});
    ASSERT_TRUE(e);
    step(*e, {{20.5f, 30.5f, 1.0f}, {2.5f, 61.5f, -0.5f}});  // one drop near an edge, to test the clamp
    for (int i = 0; i < 12; ++i) step(*e);
    expect_surface_matches_field(*e, false);
}

TEST(SurfaceSystem, WrapsTheDifferencesAroundTheEdgesOfACapillaryField) {
    // Heavy rain over a 20 cm field: ripples everywhere, the edges included.
    auto e = make_engine(make_params({"wave.model=capillary", "wave.resolution=" + std::to_string(N),
                                      "wave.size=0.2", "rain.rate=30", "rain.drift=0"}),
                         {32, 18});
    ASSERT_TRUE(e);
    for (int i = 0; i < 30; ++i) {
        begin_step_system(e->world().resource<systems::FrameClock>());
        step(*e);
    }
    expect_surface_matches_field(*e, true);
}

TEST(SurfaceSystem, StillWaterIsFlatInEveryTexel) {
    auto e = make_engine(
        make_params({"wave.model=reference", "wave.resolution=" + std::to_string(N), "rain.intensity=0"}),
        {32, 18});
    ASSERT_TRUE(e);
    auto& w = e->world();
    systems::surface_system(e->device(), w.resource<systems::WaveField>(), w.resource<systems::Surface>());
    for (const SurfaceTexel& t : read_surface(*e)) {
        ASSERT_EQ(t.height, 0.0f);
        ASSERT_EQ(t.dx, 0.0f);
        ASSERT_EQ(t.dz, 0.0f);
        ASSERT_EQ(t.splash, 0.0f) << "the reference's field has no rain, so no splashes";
    }
}

// Which texels show a splash after the next step of the capillary field in `e`.
std::vector<bool> splashes_after_step(app::Engine& e) {
    auto& w = e.world();
    begin_step_system(w.resource<systems::FrameClock>());
    step(e);
    systems::surface_system(e.device(), w.resource<systems::WaveField>(), w.resource<systems::Surface>());
    std::vector<bool> lit;
    for (const SurfaceTexel& t : read_surface(e)) lit.push_back(t.splash > 0.05f);
    return lit;
}

std::size_t count(const std::vector<bool>& v) {
    return static_cast<std::size_t>(std::count(v.begin(), v.end(), true));
}
std::size_t count_both(const std::vector<bool>& a, const std::vector<bool>& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) n += a[i] && b[i] ? 1 : 0;
    return n;
}

TEST(SurfaceSystem, SplashesAreSmallAndBrief) {
    // Heavy rain (30 mm/h) over a 20 cm field of 3.1 mm texels.
    auto e = make_engine(make_params({"wave.model=capillary", "wave.resolution=" + std::to_string(N),
                                      "wave.size=0.2", "rain.rate=30", "rain.drift=0"}),
                         {32, 18});
    ASSERT_TRUE(e);
    for (int i = 0; i < 30; ++i) splashes_after_step(*e);
    // Over 20 moments 0.15 s apart, so that no one moment's luck decides: the splashes then, a frame later
    // and 0.1 s later.
    std::size_t lit = 0, still_lit = 0, lit_later = 0, most = 0;
    for (int moment = 0; moment < 20; ++moment) {
        const std::vector<bool> now = splashes_after_step(*e);
        const std::vector<bool> next_frame = splashes_after_step(*e);
        for (int i = 0; i < 4; ++i) splashes_after_step(*e);
        const std::vector<bool> later = splashes_after_step(*e);  // 0.1 s after `now`
        for (int i = 0; i < 2; ++i) splashes_after_step(*e);
        lit += count(now);
        still_lit += count_both(now, next_frame);
        lit_later += count_both(now, later);
        most = std::max(most, count(now));
    }

    // At most one drop a 4 cm cell and 0.25 s slot: 25 cells, so about 25 * 0.06 / 0.25 = 6 splashes live
    // at once, each at most 3 drop diameters (12 mm, under 4 texels) across: some 100 texels of 4096.
    const std::size_t texels = std::size_t(N) * N;
    EXPECT_GT(lit, 20u) << "a splash where drops hit in the last 60 ms";
    EXPECT_LT(most, texels / 20) << "splashes are a few millimetres across";
    // Brief: the next frame still shows most of them; a tenth of a second later they are others.
    EXPECT_GT(still_lit, lit / 3) << "a splash lasts a few frames";
    EXPECT_LE(lit_later, lit / 10) << "a splash is gone within 0.1 s";

    // Drops with no impulse throw up nothing; no rain, no splashes.
    e->params().set(params::ParamId::rain_intensity, 0.0f, params::ParamSource::CommandLine);
    EXPECT_EQ(count(splashes_after_step(*e)), 0u);
    e->params().set(params::ParamId::rain_intensity, 0.3f, params::ParamSource::CommandLine);
    EXPECT_GT(count(splashes_after_step(*e)) + count(splashes_after_step(*e)), 0u);
    e->params().set(params::ParamId::rain_rate, 0.0f, params::ParamSource::CommandLine);
    EXPECT_EQ(count(splashes_after_step(*e)), 0u);
}

}  // namespace
}  // namespace puddle::test
