// The procedural sky's drifting clouds (assets/cloud_layer.hpp): a layer that tiles without a seam, and a
// sky cube made for it that differs from the baked one only where clouds may show.
#include "assets/cloud_layer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "assets/procedural.hpp"

namespace puddle::assets {
namespace {

float coverage_at(const Image& layer, int x, int y) {
    return static_cast<float>(layer.pixel8(x, y)[0]) / 255.0f;
}

TEST(CloudLayer, TilesWithoutASeamAndHasBothCloudAndClearSky) {
    const Image layer = cloud_layer_image();
    ASSERT_EQ(layer.width, cloud_layer_size);
    ASSERT_EQ(layer.height, cloud_layer_size);
    const int n = layer.width;
    // Across the tile's edge (last column to first) the coverage steps no more than between neighbours
    // inside it.
    double inside = 0, across = 0, clear = 0, cloudy = 0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x + 1 < n; ++x)
            inside =
                std::max<double>(inside, std::fabs(coverage_at(layer, x, y) - coverage_at(layer, x + 1, y)));
        across = std::max<double>(across, std::fabs(coverage_at(layer, n - 1, y) - coverage_at(layer, 0, y)));
        across = std::max<double>(across, std::fabs(coverage_at(layer, y, n - 1) - coverage_at(layer, y, 0)));
        for (int x = 0; x < n; ++x) {
            clear += coverage_at(layer, x, y) == 0.0f ? 1 : 0;
            cloudy += coverage_at(layer, x, y) > 0.8f ? 1 : 0;
        }
    }
    EXPECT_GT(inside, 0.0) << "the layer is not flat";
    EXPECT_LE(across, inside * 1.05 + 1.0 / 255.0) << "a seam where the tile repeats";
    EXPECT_GT(clear / (n * n), 0.2) << "broken cloud: clear sky between";
    EXPECT_GT(cloudy / (n * n), 0.02) << "and some thick cloud";
    // The bilinear read wraps: one tile further is the same coverage.
    EXPECT_NEAR(cloud_coverage(layer, 0.3f, 0.7f), cloud_coverage(layer, 1.3f, -0.3f), 1e-5f);
}

TEST(CloudLayer, TheSkyMadeForItDiffersFromTheBakedOneOnlyWhereCloudsMayShow) {
    constexpr int n = 64;
    const CubeImages baked = night_sky_cubemap(n, 7, SkyClouds::baked);
    const CubeImages drifting = night_sky_cubemap(n, 7, SkyClouds::drifting);
    int room_texels = 0, checked = 0;
    for (std::size_t face = 0; face < 6; ++face) {
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const float* b = baked.faces[face].pixelf(x, y);
                const float* d = drifting.faces[face].pixelf(x, y);
                EXPECT_EQ(b[3], 1.0f);
                ASSERT_GE(d[3], 0.0f);
                ASSERT_LE(d[3], 0.85f);
                if (face == 3) {
                    ASSERT_EQ(d[3], 0.0f) << "no cloud below the horizon (-Y face)";
                }
                if (d[3] > 0.5f) ++room_texels;
                if (d[3] ==
                    0.0f) {  // a building, the street or the horizon: no cloud in either (to float rounding:
                    // a far block drawn over the sky mixes by a coverage of 1)
                    ++checked;
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(b[c], d[c], 1e-5f * std::max(1.0f, b[c]))
                            << "face " << face << " texel " << x << "," << y;
                }
            }
        }
    }
    EXPECT_GT(room_texels, n * n / 2) << "open sky overhead has room for clouds";
    EXPECT_GT(checked, 2 * n * n) << "the street and the buildings leave none";
}

TEST(CloudLayer, TheLightMatchesTheSky) {
    const CloudLight light = night_sky_cloud_light();
    const auto& m = light.moon_direction;
    EXPECT_NEAR(std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]), 1.0, 1e-5);
    EXPECT_NEAR(std::asin(m[1]) * 180.0 / 3.14159265, 35.0, 1e-3) << "the moon 35 degrees up";
    EXPECT_GT(light.base[0], light.top[0]) << "undersides lit warm by the city";
}

}  // namespace
}  // namespace puddle::assets
