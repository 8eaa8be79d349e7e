// Wave physics on the GPU (REFERENCE.md §1): ring speed and symmetry, energy under damping, and
// frame-rate independence of the fixed-step clock.
#include <gtest/gtest.h>

#include <algorithm>

#include "support/gpu_fixture.hpp"
#include "systems/water/surface_system.hpp"
#include "systems/wave_test_support.hpp"

namespace puddle::test {
namespace {

constexpr int N = 128;
constexpr float C = 64.5f;  // the centre of texel 64: the impulse is symmetric on the grid

std::unique_ptr<app::Engine> quiet_engine(float damping) {
    return make_engine(make_params({"wave.resolution=" + std::to_string(N), "wave.model=reference",
                                    "wave.damping=" + std::to_string(damping), "rain.intensity=0"}),
                       {32, 18});
}

TEST(WaveSystem, ImpulseSpreadsAsARingAtTheSchemeSpeed) {
    auto e = quiet_engine(1.0f);
    ASSERT_TRUE(e);
    step(*e, {{C, C, 1.0f}});
    for (int i = 1; i < 20; ++i) step(*e);
    const double r20 = peak_radius(read_field(*e), C, C);
    for (int i = 20; i < 40; ++i) step(*e);
    const double r40 = peak_radius(read_field(*e), C, C);
    // c^2 dt^2 / dx^2 = 1/2: waves travel sqrt(1/2) = 0.707 texels per step.
    const double speed = (r40 - r20) / 20.0;
    EXPECT_NEAR(speed, std::sqrt(0.5), 0.1) << "r20 " << r20 << " r40 " << r40;
    EXPECT_GT(r20, 8.0);
}

namespace {
unsigned step_program_of(const systems::WaveField& field) {
    const render::BuiltPipeline* p = field.step_pipelines.find(field.variant());
    return p ? p->pipeline.id() : 0;
}
unsigned surface_program_of(const systems::Surface& surface) {
    const render::BuiltPipeline* p = surface.pipelines.find(surface.variant());
    return p ? p->pipeline.id() : 0;
}
}  // namespace

// A new wave.resolution remakes the textures but keeps the compiled step and surface shaders: compiling
// them again on every rebuild grew resident memory by about 65 KiB a time on llvmpipe (puddle-soak).
TEST(WaveSystem, NewResolutionKeepsTheCompiledPipelinesAndGivesAFlatFieldOfTheNewSize) {
    auto e = quiet_engine(0.99f);
    ASSERT_TRUE(e);
    auto& field = e->world().resource<systems::WaveField>();
    auto& surface = e->world().resource<systems::Surface>();
    const unsigned step_program = step_program_of(field), surface_program = surface_program_of(surface);
    step(*e, {{C, C, 1.0f}});
    auto params = make_params({"wave.model=reference", "wave.resolution=96"});
    ASSERT_TRUE(systems::build_wave_field(e->device(), params, field));
    ASSERT_TRUE(systems::build_surface(e->device(), field, surface));
    EXPECT_EQ(step_program_of(field), step_program);
    EXPECT_EQ(surface_program_of(surface), surface_program);
    const Field f = read_field(*e);
    ASSERT_EQ(f.n, 96);
    EXPECT_EQ(std::count(f.hv.begin(), f.hv.end(), 0.0f), 96 * 96 * 2) << "the new field starts flat";
}

// The same through the live path (the wave rebuild system, which builds field and surface both or
// neither): a wave.resolution edit while running compiles nothing on the frame thread.
TEST(WaveSystem, ALiveResolutionEditKeepsTheCompiledPipelines) {
    auto e = quiet_engine(0.99f);
    ASSERT_TRUE(e);
    render_frames(*e, 2);
    const auto& field = e->world().resource<systems::WaveField>();
    const auto& surface = e->world().resource<systems::Surface>();
    const unsigned step_program = step_program_of(field), surface_program = surface_program_of(surface);
    ASSERT_NE(step_program, 0u);
    e->params().set(params::ParamId::wave_resolution, 96, params::ParamSource::CommandLine);
    render_frames(*e, 1);
    ASSERT_EQ(field.resolution, 96);
    ASSERT_EQ(surface.resolution, 96);
    EXPECT_EQ(step_program_of(field), step_program);
    EXPECT_EQ(surface_program_of(surface), surface_program);
}

// The field's encoding switched (wave.float_field) and back: each encoding's shaders are compiled once, so
// the way back compiles nothing (before the pipeline cache, every switch compiled both shaders again).
TEST(WaveSystem, SwitchingTheFieldEncodingAndBackCompilesEachEncodingOnce) {
    auto e = quiet_engine(0.99f);
    ASSERT_TRUE(e);
    if (!e->device().caps().float_render_targets) GTEST_SKIP() << "this GPU has the fixed-point field only";
    render_frames(*e, 1);
    const auto& field = e->world().resource<systems::WaveField>();
    const auto& surface = e->world().resource<systems::Surface>();
    const bool started_fixed = field.fixed_point;
    const unsigned step_program = step_program_of(field), surface_program = surface_program_of(surface);
    ASSERT_NE(step_program, 0u);
    e->params().set(params::ParamId::wave_float_field, started_fixed, params::ParamSource::CommandLine);
    render_frames(*e, 1);
    ASSERT_NE(field.fixed_point, started_fixed);
    EXPECT_NE(step_program_of(field), step_program) << "the other encoding has its own step shader";
    e->params().set(params::ParamId::wave_float_field, !started_fixed, params::ParamSource::CommandLine);
    render_frames(*e, 1);
    ASSERT_EQ(field.fixed_point, started_fixed);
    EXPECT_EQ(step_program_of(field), step_program);
    EXPECT_EQ(surface_program_of(surface), surface_program);
}

TEST(WaveSystem, RingStaysSymmetric) {
    auto e = quiet_engine(0.99f);
    ASSERT_TRUE(e);
    step(*e, {{C, C, 1.0f}});
    for (int i = 1; i < 30; ++i) step(*e);
    const Field f = read_field(*e);
    double peak = 0, worst = 0;
    const int c = 64;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            const int mx = 2 * c - x, my = 2 * c - y;
            if (mx < 0 || mx >= N || my < 0 || my >= N) continue;
            peak = std::max(peak, std::abs(f.cur(x, y)));
            worst =
                std::max({worst, std::abs(f.cur(x, y) - f.cur(mx, y)), std::abs(f.cur(x, y) - f.cur(x, my)),
                          std::abs(f.cur(x, y) - f.cur(y, x))});  // mirror x, mirror y, transpose
        }
    ASSERT_GT(peak, 1e-3);
    EXPECT_LT(worst, 1e-4 * std::max(peak, 1.0)) << "peak " << peak;
}

TEST(WaveSystem, EnergyFallsWithDamping) {
    auto e = quiet_engine(0.98f);
    ASSERT_TRUE(e);
    step(*e, {{C, C, 1.0f}});
    double last = energy(read_field(*e));
    const double first = last;
    for (int block = 0; block < 10; ++block) {
        for (int i = 0; i < 20; ++i) step(*e);
        const double now = energy(read_field(*e));
        EXPECT_LT(now, last) << "after " << (block + 1) * 20 << " steps";
        last = now;
    }
    EXPECT_LT(last, 0.05 * first);  // 0.98^200 of the amplitude is about 2%
}

TEST(WaveSystem, EnergyStaysBoundedWithoutDampingOver10000Steps) {
    auto e = quiet_engine(1.0f);
    ASSERT_TRUE(e);
    step(*e, {{C, C, 1.0f}});
    step(*e);
    const double start = energy(read_field(*e));
    ASSERT_GT(start, 0.0);
    double lo = start, hi = start;
    for (int block = 0; block < 20; ++block) {
        for (int i = 0; i < 500; ++i) step(*e);
        const double now = energy(read_field(*e));
        lo = std::min(lo, now);
        hi = std::max(hi, now);
    }
    // The scheme conserves this energy exactly in exact arithmetic; float rounding may move it a little.
    EXPECT_LT(hi, start * 1.05) << "energy grew";
    EXPECT_GT(lo, start * 0.95) << "energy leaked";
}

TEST(WaveSystem, SameSimulatedTimeGivesTheSameFieldAt30And144Fps) {
    auto params = make_params({"wave.resolution=128", "rain.drop_count=30", "rain.seed=5"});
    auto a = make_engine(params, {32, 18});
    auto b = make_engine(params, {32, 18});
    ASSERT_TRUE(a && b);
    render_frames(*a, 60, 1.0 / 30.0);    // 2 s
    render_frames(*b, 288, 1.0 / 144.0);  // 2 s
    EXPECT_EQ(a->world().resource<systems::FrameClock>().step_index, 120u);
    EXPECT_EQ(b->world().resource<systems::FrameClock>().step_index, 120u);
    const Field fa = read_field(*a), fb = read_field(*b);
    float peak = 0;
    for (float v : fa.hv) peak = std::max(peak, std::abs(v));
    ASSERT_GT(peak, 0.01f) << "the rain should have disturbed the field";
    EXPECT_EQ(fa.hv, fb.hv);
}

// rain.seed chooses the capillary rain (rain_slot_key): the same seed gives the same field, another seed
// other drops, which leave the field different nearly everywhere.
TEST(WaveSystem, TheRainSeedChoosesWhereTheCapillaryRainFalls) {
    const auto with_seed = [](int seed) {
        auto e = make_engine(make_params({"wave.model=capillary", "wave.resolution=128", "rain.rate=8",
                                          "rain.drift=0", "rain.seed=" + std::to_string(seed)}),
                             {32, 18});
        EXPECT_TRUE(e);
        if (e) render_frames(*e, 60, 1.0 / 60.0);  // 1 s of rain
        return e ? read_field(*e).hv : std::vector<float>{};
    };
    const std::vector<float> a = with_seed(5), b = with_seed(5), c = with_seed(6);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b) << "the same seed and time must give the same rain on every screen";
    ASSERT_EQ(a.size(), c.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += std::abs(a[i] - c[i]) > 1e-3f ? 1 : 0;
    EXPECT_GT(differ, a.size() / 4) << "another seed must make other rain";
}

}  // namespace
}  // namespace puddle::test
