// Grid-sampled drops (REFERENCE.md section 5): no drop reaches past its 3x3 cells, so testing only those
// nine loses nothing, and the rings come and go with the cycle.
#include "systems/grid_drops/grid_drop_system.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu_fixture.hpp"

namespace puddle::test {
namespace {

using systems::GridDrops;

constexpr int N = 128;

// Widest rings allowed (a quarter cell): the limit case of the 3x3 rule.
std::unique_ptr<app::Engine> grid_engine() {
    return make_engine(make_params({"wave.resolution=" + std::to_string(N), "drops.model=grid",
                                    "grid.ring_width=0.25", "grid.drops_per_second=20", "grid.cycle=1.25"}),
                       {32, 18});
}

std::vector<float> draw(app::Engine& e, const GridDrops& grid, double now, glm::ivec2 only_cell = {-1, -1}) {
    auto& surface = e.world().resource<systems::Surface>();
    systems::grid_drop_pass(e.device(), e.params(), now, grid, surface, only_cell);
    return e.device().read_texture(surface.texture);
}

TEST(GridDrops, NoDropReachesPastItsThreeByThreeCells) {
    auto e = grid_engine();
    ASSERT_TRUE(e);
    const auto& surface = e->world().resource<systems::Surface>();
    GridDrops reach2;  // tests 5x5 cells: sees anything a 3x3 search would miss
    ASSERT_TRUE(systems::prepare_grid_drops(e->device(), surface, reach2, 2).ok());
    const float cell = systems::grid_cell_texels(e->params(), N);
    ASSERT_NEAR(cell, N / 5.0, 1e-3);  // 20 drops/s * 1.25 s = 25 cells
    const glm::ivec2 home{2, 2};
    double lit = 0;
    for (int k = 0; k < 12; ++k) {  // across a whole cycle: every age of the drop
        const double now = 100.0 + k * 1.25 / 12;
        const std::vector<float> t = draw(*e, reach2, now, home);
        for (int y = 0; y < N; ++y)
            for (int x = 0; x < N; ++x) {
                const float h = t[(std::size_t(y) * N + x) * 4];
                if (h == 0.0f) continue;
                lit += 1;
                const int cx = int(std::floor((x + 0.5) / cell)), cy = int(std::floor((y + 0.5) / cell));
                ASSERT_LE(std::abs(cx - home.x), 1) << "texel " << x << "," << y << " at " << now;
                ASSERT_LE(std::abs(cy - home.y), 1) << "texel " << x << "," << y << " at " << now;
            }
    }
    EXPECT_GT(lit, 500) << "the isolated drop made rings";
}

TEST(GridDrops, ThreeByThreeGivesTheSameSurfaceAsFiveByFive) {
    auto e = grid_engine();
    ASSERT_TRUE(e);
    const auto& surface = e->world().resource<systems::Surface>();
    GridDrops reach1, reach2;
    ASSERT_TRUE(systems::prepare_grid_drops(e->device(), surface, reach1, 1).ok());
    ASSERT_TRUE(systems::prepare_grid_drops(e->device(), surface, reach2, 2).ok());
    double peak = 0;
    for (double now : {3.1, 7.77, 12.4}) {
        const std::vector<float> a = draw(*e, reach1, now), b = draw(*e, reach2, now);
        ASSERT_EQ(a.size(), b.size());
        double worst = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            worst = std::max(worst, double(std::abs(a[i] - b[i])));
            peak = std::max(peak, double(std::abs(a[i])));
        }
        EXPECT_LT(worst, 1e-3) << "at " << now;
    }
    EXPECT_GT(peak, 0.05);
}

TEST(GridDrops, MoreDropsMeanSmallerCells) {
    const params::Params few = make_params({"grid.drops_per_second=10", "grid.cycle=1"});
    const params::Params many = make_params({"grid.drops_per_second=1000", "grid.cycle=1"});
    EXPECT_NEAR(systems::grid_cell_texels(few, 512), 512 / std::sqrt(10.0), 1e-3);
    EXPECT_NEAR(systems::grid_cell_texels(many, 512), 512 / std::sqrt(1000.0), 1e-3);
}

TEST(GridDrops, RingsMoveWithTime) {
    auto e = grid_engine();
    ASSERT_TRUE(e);
    const auto& grid = e->world().resource<GridDrops>();
    const std::vector<float> a = draw(*e, grid, 5.0), b = draw(*e, grid, 5.3), a_again = draw(*e, grid, 5.0);
    double moved = 0;
    for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, double(std::abs(a[i] - b[i])));
    EXPECT_GT(moved, 0.05);
    EXPECT_EQ(a, a_again) << "the same time gives the same drops";
}

}  // namespace
}  // namespace puddle::test
