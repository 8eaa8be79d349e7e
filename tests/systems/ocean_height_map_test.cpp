// Where the ocean's height map lies (systems/ocean/ocean_height_map.hpp): it covers every point of the plane
// of the highest crest that a ray of the target reads between entering the waves and reaching the floor,
// at half the target's pixels per side, and there is none where the eye is too low for it.
#include "systems/ocean/ocean_height_map.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "render/view_basis.hpp"

namespace puddle::test {
namespace {

using systems::OceanHeightMapLayout;

constexpr glm::vec3 eye{0, 4, 5};
constexpr glm::ivec2 target{320, 180};
const float highest = systems::ocean_highest_wave(0.6f, 5);

render::ViewBasis view_of(glm::vec3 from, glm::vec3 at) {
    return render::view_basis(from, at, 60, 16.0f / 9);
}

// Where the eye sees q, in the view's uv.
glm::vec2 seen_at(const render::ViewBasis& v, glm::vec3 from, glm::vec3 q) {
    const glm::vec3 d = q - from;
    const float z = glm::dot(d, v.forward);
    return glm::vec2(glm::dot(d, v.right) / (z * v.scale.x), glm::dot(d, v.up) / (z * v.scale.y)) * 0.5f +
           0.5f;
}

bool covers(const OceanHeightMapLayout& m, glm::vec2 uv) {
    return uv.x >= m.origin.x && uv.y >= m.origin.y && uv.x <= m.origin.x + m.extent.x &&
           uv.y <= m.origin.y + m.extent.y;
}

TEST(OceanHeightMap, HighestWaveSumsEveryOctavesTwoTerms) {
    EXPECT_FLOAT_EQ(systems::ocean_highest_wave(0.6f, 1), 1.2f);
    EXPECT_NEAR(systems::ocean_highest_wave(0.6f, 3), 1.2f * (1 + 0.22f + 0.0484f), 1e-6);
    EXPECT_FLOAT_EQ(systems::ocean_highest_wave(0.0f, 5), 0.0f);
}

// Every point the march reads, on a fine grid of the target's rays and along each between its entry into
// the waves and the floor, lies in the map; the map is no larger than it needs to be by much.
TEST(OceanHeightMap, CoversEveryPointTheRaysOfTheTargetRead) {
    const render::ViewBasis v = view_of(eye, {0, 3, -10});
    const OceanHeightMapLayout m = systems::ocean_height_map_layout(v, eye, highest, {}, target);
    ASSERT_FALSE(m.empty());
    EXPECT_FLOAT_EQ(m.plane, highest);
    int reads = 0;
    for (int j = 0; j <= 40; ++j)
        for (int i = 0; i <= 40; ++i) {
            const glm::vec2 uv{i / 40.0f, j / 40.0f};
            const glm::vec2 ndc = uv * 2.0f - 1.0f;
            const glm::vec3 dir =
                glm::normalize(v.forward + ndc.x * v.scale.x * v.right + ndc.y * v.scale.y * v.up);
            if (dir.y >= -1e-4f) continue;
            const float t_near = (eye.y - highest) / -dir.y;
            const float t_far = std::min(eye.y / -dir.y, systems::ocean_far);
            for (int k = 0; k <= 10 && t_near < t_far; ++k) {
                const glm::vec3 p = eye + dir * (t_near + (t_far - t_near) * k / 10.0f);
                EXPECT_TRUE(covers(m, seen_at(v, eye, {p.x, highest, p.z}))) << i << ", " << j << ", " << k;
                ++reads;
            }
        }
    EXPECT_GT(reads, 5000);
    // Below the horizon (0.44 of the view from its top) and a margin: not the sky above.
    EXPECT_LT(m.origin.y + m.extent.y, 0.65f);
    EXPECT_GT(m.origin.y + m.extent.y, 0.5f);
    // Half the target's pixels per side over the part it covers.
    EXPECT_NEAR(m.size.x, m.extent.x * target.x * systems::ocean_height_map_scale, 1.0);
    EXPECT_NEAR(m.size.y, m.extent.y * target.y * systems::ocean_height_map_scale, 1.0);
}

// A video wall's tile: its map lies within the whole view's (plus a margin) and is as fine as the whole
// view's, so the tiles read the same heights as the whole view does.
TEST(OceanHeightMap, ATilesMapIsTheWholeViewsAsFine) {
    const render::ViewBasis v = view_of(eye, {0, 3, -10});
    const OceanHeightMapLayout whole = systems::ocean_height_map_layout(v, eye, highest, {}, target * 2);
    const render::ViewWindow tile{.origin = {0.5f, 0.0f}, .extent = {0.5f, 0.5f}};
    const OceanHeightMapLayout part = systems::ocean_height_map_layout(v, eye, highest, tile, target);
    ASSERT_FALSE(part.empty());
    EXPECT_GE(part.origin.x, whole.origin.x - 0.05f);
    EXPECT_LE(part.origin.x + part.extent.x, whole.origin.x + whole.extent.x + 0.05f);
    EXPECT_NEAR(part.size.x / part.extent.x, whole.size.x / whole.extent.x, 2.0 / part.extent.x);
    EXPECT_NEAR(part.size.y / part.extent.y, whole.size.y / whole.extent.y, 2.0 / part.extent.y);
}

TEST(OceanHeightMap, NoneForAnEyeAmongTheCrestsOrAViewOfSkyAlone) {
    const glm::vec3 low{0, systems::ocean_height_map_min_eye(highest) - 0.01f, 5};
    EXPECT_TRUE(
        systems::ocean_height_map_layout(view_of(low, {0, 0, -10}), low, highest, {}, target).empty());
    const glm::vec3 just{0, systems::ocean_height_map_min_eye(highest) + 0.01f, 5};
    EXPECT_FALSE(
        systems::ocean_height_map_layout(view_of(just, {0, 0, -10}), just, highest, {}, target).empty());
    EXPECT_TRUE(
        systems::ocean_height_map_layout(view_of(eye, {0, 40, -10}), eye, highest, {}, target).empty())
        << "looking up at the sky";
}

}  // namespace
}  // namespace puddle::test
