// The camera's basis (render/view_basis.hpp): right-handed and orthonormal, no roll, the image plane
// scaled by tan(fov / 2), and sensible axes when looking straight up or at the eye itself.
#include "render/view_basis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace puddle::render {
namespace {

void expect_orthonormal(const ViewBasis& b) {
    EXPECT_NEAR(glm::length(b.forward), 1, 1e-6);
    EXPECT_NEAR(glm::length(b.right), 1, 1e-6);
    EXPECT_NEAR(glm::length(b.up), 1, 1e-6);
    EXPECT_NEAR(glm::dot(b.forward, b.right), 0, 1e-6);
    EXPECT_NEAR(glm::dot(b.forward, b.up), 0, 1e-6);
    EXPECT_NEAR(glm::dot(b.right, b.up), 0, 1e-6);
}

TEST(ViewBasis, LooksAtTheTargetWithoutRoll) {
    const glm::vec3 eye{0, 4, 5}, target{0, 3, -10};
    const ViewBasis b = view_basis(eye, target, 60, 16.0f / 9);
    expect_orthonormal(b);
    const glm::vec3 to_target = glm::normalize(target - eye);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(b.forward[c], to_target[c], 1e-6);
    EXPECT_NEAR(b.right.y, 0, 1e-6) << "no roll: right stays level";
    EXPECT_GT(b.up.y, 0) << "up points up";
    EXPECT_GT(b.right.x, 0) << "looking down -z, right is +x";
}

TEST(ViewBasis, ScalesTheImagePlaneByTheFieldOfView) {
    const ViewBasis b = view_basis({0, 0, 0}, {0, 0, -1}, 90, 2.0f);
    EXPECT_NEAR(b.scale.y, 1.0, 1e-6) << "tan(45 degrees)";
    EXPECT_NEAR(b.scale.x, 2.0, 1e-6) << "times the aspect";
    EXPECT_NEAR(view_basis({0, 0, 0}, {0, 0, -1}, 60, 1.0f).scale.y, std::tan(3.14159265 / 6), 1e-6);
}

// Straight up or down, forward x world-up is zero: right falls back to +x, and the basis stays whole.
TEST(ViewBasis, LookingStraightUpOrDownOrAtTheEyeStillGivesABasis) {
    const ViewBasis down = view_basis({0, 10, 0}, {0, 0, 0}, 60, 1.0f);
    expect_orthonormal(down);
    EXPECT_NEAR(down.forward.y, -1, 1e-6);
    EXPECT_NEAR(down.right.x, 1, 1e-6);
    const ViewBasis same = view_basis({1, 2, 3}, {1, 2, 3}, 60, 1.0f);
    expect_orthonormal(same);
    EXPECT_EQ(same.forward, ViewBasis{}.forward) << "the default forward";
}

}  // namespace
}  // namespace puddle::render
