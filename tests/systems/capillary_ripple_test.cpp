// The capillary wave model on the GPU (wave.model = capillary): one drop on calm water, its radial
// profile at fixed times. Rain on a puddle leaves a train of thin rings about a centimetre apart that
// spread at 0.2 to 0.3 m/s and leave the centre calm (shared LOOK.md, "Rain on shallow water").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/gpu_fixture.hpp"
#include "systems/wave_test_support.hpp"

namespace puddle::test {
namespace {

struct FieldSize {
    int resolution;
    double size_m;
};

std::unique_ptr<app::Engine> calm_engine(FieldSize s) {
    return make_engine(make_params({"wave.model=capillary", "wave.resolution=" + std::to_string(s.resolution),
                                    "wave.size=" + std::to_string(s.size_m), "rain.rate=0", "rain.drift=0"}),
                       {32, 18});
}

// One fixed step (1/60 s) with a drop of `diameter_mm` at the field's centre, `age` seconds after it hit
// at the step's end.
void step_with_drop(app::Engine& e, double age, float diameter_mm) {
    const auto& field = e.world().resource<systems::WaveField>();
    const float centre = 0.5f * static_cast<float>(field.resolution);
    systems::LiveDrops live;
    live.drops[0] = glm::vec4(centre, centre, diameter_mm, static_cast<float>(age));
    live.count = 1;
    e.make_current();
    systems::wave_system(e.device(), e.params(), e.world().resource<systems::FrameClock>(), live,
                         e.world().resource<systems::WaveField>());
}

// Height against distance from the centre, averaged over the angle, in bins of half a millimetre.
struct Profile {
    double bin_m = 0.0005;
    std::vector<double> height;
    double at_m(double r) const { return height[std::min(height.size() - 1, std::size_t(r / bin_m))]; }
};

Profile radial_profile(const Field& f, double size_m) {
    const double texel = size_m / f.n, c = 0.5 * f.n;
    Profile p;
    const auto bins = std::size_t(0.5 * size_m / p.bin_m);
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (int y = 0; y < f.n; ++y)
        for (int x = 0; x < f.n; ++x) {
            const double r = std::hypot(x + 0.5 - c, y + 0.5 - c) * texel;  // texel centres
            const auto b = std::size_t(r / p.bin_m);
            if (b < bins) sum[b] += f.cur(x, y), count[b] += 1;
        }
    p.height.resize(bins);
    for (std::size_t i = 0; i < bins; ++i) p.height[i] = count[i] > 0 ? sum[i] / count[i] : 0.0;
    return p;
}

struct Crest {
    double radius_m;
    double height;
    double width_m;  // full width at half its height
};

// Crests: local maxima above a tenth of the tallest, with their full width at half height.
std::vector<Crest> crests(const Profile& p) {
    double tallest = 0.0;
    for (double h : p.height) tallest = std::max(tallest, h);
    std::vector<Crest> out;
    for (std::size_t i = 2; i + 2 < p.height.size(); ++i) {
        const double h = p.height[i];
        if (h < 0.1 * tallest || h < p.height[i - 1] || h < p.height[i + 1] || h < p.height[i - 2] ||
            h < p.height[i + 2])
            continue;
        std::size_t lo = i, hi = i;
        while (lo > 0 && p.height[lo] > 0.5 * h) --lo;
        while (hi + 1 < p.height.size() && p.height[hi] > 0.5 * h) ++hi;
        out.push_back({(i + 0.5) * p.bin_m, h, double(hi - lo) * p.bin_m});
        i = hi;
    }
    return out;
}

std::string describe(const std::vector<Crest>& cs) {
    std::string s;
    for (const Crest& c : cs)
        s += "r " + std::to_string(c.radius_m * 100) + " cm h " + std::to_string(c.height) + " fwhm " +
             std::to_string(c.width_m * 1000) + " mm; ";
    return s;
}

// Steps a drop's ring train to `until` seconds and returns the profile then.
Profile after(app::Engine& e, FieldSize s, int& steps_done, double until, float diameter_mm = 3.0f) {
    for (; (steps_done + 1) / 60.0 <= until + 1e-9; ++steps_done)
        step_with_drop(e, (steps_done + 1) / 60.0, diameter_mm);
    return radial_profile(read_field(e), s.size_m);
}

TEST(CapillaryRipples, OneDropMakesATrainOfThinRingsAndACalmCentre) {
    const FieldSize s{256, 0.8};  // 3.125 mm texels, as the default 512 over 1.6 m
    auto e = calm_engine(s);
    ASSERT_TRUE(e);
    int steps = 0;
    const Profile early = after(*e, s, steps, 0.4);
    const std::vector<Crest> rings = crests(early);
    ASSERT_GE(rings.size(), 3u) << "at 0.4 s: " << describe(rings);
    double tallest = 0.0;
    for (const Crest& c : rings) tallest = std::max(tallest, c.height);
    for (std::size_t i = 0; i + 1 < rings.size() && i < 3; ++i) {
        const double spacing = rings[i + 1].radius_m - rings[i].radius_m;
        EXPECT_GT(spacing, 0.005) << "rings a centimetre or two apart: " << describe(rings);
        EXPECT_LT(spacing, 0.03) << describe(rings);
        EXPECT_LT(rings[i].width_m, 0.5 * spacing)
            << "each ring much thinner than the spacing: " << describe(rings);
    }
    // The centre is calm again within a fraction of a second: within 1 cm of the impact the water is
    // under a fifth of the rings' height.
    for (double r = 0.0; r < 0.01; r += early.bin_m)
        EXPECT_LT(std::abs(early.at_m(r)), 0.2 * tallest) << "at " << r * 100 << " cm, 0.4 s";

    // The train spreads at 0.15 to 0.35 m/s: its outermost crest between 0.4 and 0.6 s.
    const double front_early = rings.back().radius_m;
    const std::vector<Crest> later = crests(after(*e, s, steps, 0.6));
    ASSERT_FALSE(later.empty());
    const double speed = (later.back().radius_m - front_early) / 0.2;
    EXPECT_GT(speed, 0.15) << describe(rings) << " then " << describe(later);
    EXPECT_LT(speed, 0.35) << describe(rings) << " then " << describe(later);

    // Gone within a couple of seconds: at 2 s nothing is left over a tenth of the early rings' height.
    const Profile gone = after(*e, s, steps, 2.0);
    double rest = 0.0;
    for (double h : gone.height) rest = std::max(rest, std::abs(h));
    EXPECT_LT(rest, 0.1 * tallest);
}

// The physics is in metres and seconds: a finer field (2.5 mm texels) puts the rings at the same radii.
TEST(CapillaryRipples, TheRingsSitAtTheSameRadiiAtAnotherResolution) {
    const FieldSize coarse{256, 0.8}, fine{320, 0.8};
    auto a = calm_engine(coarse), b = calm_engine(fine);
    ASSERT_TRUE(a && b);
    int steps_a = 0, steps_b = 0;
    const std::vector<Crest> ra = crests(after(*a, coarse, steps_a, 0.4));
    const std::vector<Crest> rb = crests(after(*b, fine, steps_b, 0.4));
    ASSERT_FALSE(ra.empty());
    ASSERT_FALSE(rb.empty());
    EXPECT_NEAR(ra.back().radius_m, rb.back().radius_m, 0.004) << describe(ra) << " / " << describe(rb);
    EXPECT_NEAR(ra.front().radius_m, rb.front().radius_m, 0.004) << describe(ra) << " / " << describe(rb);
}

// Bigger drops make bigger rings (shared LOOK.md, "Drops").
TEST(CapillaryRipples, ABiggerDropMakesTallerRings) {
    const FieldSize s{256, 0.8};
    auto small = calm_engine(s), big = calm_engine(s);
    ASSERT_TRUE(small && big);
    int steps_small = 0, steps_big = 0;
    const std::vector<Crest> rs = crests(after(*small, s, steps_small, 0.4, 1.5f));
    const std::vector<Crest> rb = crests(after(*big, s, steps_big, 0.4, 3.5f));
    ASSERT_FALSE(rs.empty());
    ASSERT_FALSE(rb.empty());
    double hs = 0.0, hb = 0.0;
    for (const Crest& c : rs) hs = std::max(hs, c.height);
    for (const Crest& c : rb) hb = std::max(hb, c.height);
    EXPECT_GT(hb, 2.0 * hs);
}

}  // namespace
}  // namespace puddle::test
