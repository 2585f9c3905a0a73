// intersect_triangle: the plane hit, kept when its barycentric coordinates b1, b2 >= 0 and
// b1 + b2 <= 1; uv = (b1, b2), the weights of p1 and p2.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

// Outward normal normalize((2, 0, 0) x (0, 0, 3)) = normalize(0, -6, 0) = (0, -1, 0).
// A point (x, 1, z) has b1 = (x - 1) / 2 and b2 = (z - 1) / 3.
const Triangle kTriangle{{1, 1, 1}, {3, 1, 1}, {1, 1, 4}};

/// The ray that arrives at (x, 1, z) from y = -2, going up (+y), t = 3.
Ray ray_up_to(double x, double z) { return make_ray({x, -2, z}, {0, 1, 0}); }

} // namespace

TEST(IntersectTriangle, HitReportsBarycentricsOfP1AndP2) {
    // (1.5, 1, 2.5): b1 = 0.25, b2 = 0.5, so p = 0.25 p0 + 0.25 p1 + 0.5 p2; from y = -2, t = 3.
    const auto hit = intersect_triangle(ray_up_to(1.5, 2.5), kTriangle, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {1.5, 1, 2.5}));
    EXPECT_NEAR(hit->uv.x, 0.25, 1e-12) << "uv.x is b1, the weight of p1";
    EXPECT_NEAR(hit->uv.y, 0.5, 1e-12) << "uv.y is b2, the weight of p2";
    EXPECT_TRUE(near(hit->normal, {0, -1, 0})) << "outward normal normalize(cross(p1 - p0, p2 - p0))";
    EXPECT_TRUE(hit->front_face) << "p0, p1, p2 look counter-clockwise from below: the ray meets the front";
}

TEST(IntersectTriangle, RayFromTheBackSeesTheBackFace) {
    const auto hit = intersect_triangle(make_ray({1.5, 4, 2.5}, {0, -1, 0}), kTriangle, {});
    ASSERT_TRUE(hit) << "triangles are two-sided";
    EXPECT_NEAR(hit->t, 3.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 1, 0})) << "the normal must be turned to face the ray";
    EXPECT_FALSE(hit->front_face);
}

TEST(IntersectTriangle, ObliqueRayReportsTheSlantDistanceAndBarycentrics) {
    // Triangle (0,0,0), (2,0,0), (0,2,0), normal +z. From (1.5, 1.5, 2) along (-1, -1, -2) it reaches
    // (0.5, 0.5, 0) at t = |(1, 1, 2)| = sqrt(6): b1 = 0.5 / 2 = 0.25, b2 = 0.25.
    const Triangle triangle{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    const auto hit = intersect_triangle(make_ray({1.5, 1.5, 2}, {-1, -1, -2}), triangle, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(6.0), 1e-12);
    EXPECT_TRUE(near(hit->point, {0.5, 0.5, 0}, 1e-12));
    EXPECT_NEAR(hit->uv.x, 0.25, 1e-12);
    EXPECT_NEAR(hit->uv.y, 0.25, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0, 1}));
    EXPECT_TRUE(hit->front_face);
}

TEST(IntersectTriangle, PointsBeyondEachEdgeAreMissed) {
    // Beyond p0p2 (x < 1): b1 = -0.05.
    EXPECT_FALSE(intersect_triangle(ray_up_to(0.9, 2), kTriangle, {})) << "b1 < 0: outside the edge p0 p2";
    // Beyond p0p1 (z < 1): b2 = -0.05 / 3.
    EXPECT_FALSE(intersect_triangle(ray_up_to(2, 0.95), kTriangle, {})) << "b2 < 0: outside the edge p0 p1";
    // Beyond the hypotenuse p1p2: (2.9, 1, 3.9) has b1 = 0.95 and b2 = 0.9667, both in [0, 1],
    // but b1 + b2 > 1. Checking b1 <= 1 and b2 <= 1 alone would accept a parallelogram.
    EXPECT_FALSE(intersect_triangle(ray_up_to(2.9, 3.9), kTriangle, {}))
        << "b1 + b2 > 1: outside the edge p1 p2 (check b1 + b2 <= 1)";
    EXPECT_FALSE(intersect_triangle(ray_up_to(2.5, 2.5), kTriangle, {})) << "b1 = 0.75, b2 = 0.5: b1 + b2 > 1";
    // Just inside each edge instead, the ray meets the triangle (t = 3): (1.1, 1, 2) has b1 = 0.05,
    // (2, 1, 1.05) has b2 = 0.05 / 3, (2, 1, 2.35) has b1 + b2 = 0.5 + 0.45 = 0.95.
    for (const auto& [x, z, b1, b2] : {std::array{1.1, 2.0, 0.05, 1.0 / 3.0}, std::array{2.0, 1.05, 0.5, 0.05 / 3.0},
                                       std::array{2.0, 2.35, 0.5, 0.45}}) {
        const auto hit = intersect_triangle(ray_up_to(x, z), kTriangle, {});
        ASSERT_TRUE(hit) << "(" << x << ", 1, " << z << ") is just inside the triangle";
        EXPECT_NEAR(hit->t, 3.0, 1e-12);
        EXPECT_NEAR(hit->uv.x, b1, 1e-12);
        EXPECT_NEAR(hit->uv.y, b2, 1e-12);
    }
}

TEST(IntersectTriangle, EdgeAndVertexPointsCountAsHits) {
    // Midpoint of p0p1: b1 = 0.5, b2 = 0 exactly (all arithmetic here is exact).
    const auto edge = intersect_triangle(ray_up_to(2, 1), kTriangle, {});
    ASSERT_TRUE(edge) << "points on an edge belong to the triangle";
    EXPECT_EQ(edge->uv, Vec2(0.5, 0.0));
    // The vertex p2: b1 = 0, b2 = 1, b1 + b2 = 1.
    const auto vertex = intersect_triangle(ray_up_to(1, 4), kTriangle, {});
    ASSERT_TRUE(vertex) << "vertices belong to the triangle";
    EXPECT_EQ(vertex->uv, Vec2(0.0, 1.0));
}

TEST(IntersectTriangle, TinyTriangleIsHitAndItsEdgesKept) {
    // Legs 1e-3 along x and 5e-4 along y in z = 0: e1 x e2 = (0, 0, 5e-7), normal +z. From (2e-4, 1e-4, 1)
    // along -z: t = 1 at b1 = 2e-4 / 1e-3 = 0.2, b2 = 1e-4 / 5e-4 = 0.2. The determinant e1 . (d x e2)
    // is 5e-7 here: only det == 0 means a parallel ray (a fixed "det < 1e-6" loses every small triangle).
    const Triangle tiny{{0, 0, 0}, {1e-3, 0, 0}, {0, 5e-4, 0}};
    const auto hit = intersect_triangle(make_ray({2e-4, 1e-4, 1}, {0, 0, -1}), tiny, {});
    ASSERT_TRUE(hit) << "a triangle with millimetre edges is still a triangle: no fixed epsilon on the determinant";
    EXPECT_NEAR(hit->t, 1.0, 1e-12);
    EXPECT_NEAR(hit->uv.x, 0.2, 1e-12);
    EXPECT_NEAR(hit->uv.y, 0.2, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0, 1}));
    // (6e-4, 3e-4): b1 = 0.6, b2 = 0.6, b1 + b2 > 1: beyond the hypotenuse.
    EXPECT_FALSE(intersect_triangle(make_ray({6e-4, 3e-4, 1}, {0, 0, -1}), tiny, {}));
}

TEST(IntersectTriangle, ParallelRayAndTriangleBehindAreMissed) {
    EXPECT_FALSE(intersect_triangle(make_ray({1.5, 1, -5}, {0, 0, 1}), kTriangle, {}))
        << "a ray inside the triangle's plane has no single hit";
    EXPECT_FALSE(intersect_triangle(make_ray({1.5, 4, 2.5}, {0, 1, 0}), kTriangle, {}))
        << "the triangle is at t = -3, behind the origin";
    // Turned around (going down), the ray meets the triangle 3 below, at (1.5, 1, 2.5): b1 = 0.25, b2 = 0.5.
    const auto ahead = intersect_triangle(make_ray({1.5, 4, 2.5}, {0, -1, 0}), kTriangle, {});
    ASSERT_TRUE(ahead) << "going down, the triangle is ahead";
    EXPECT_NEAR(ahead->t, 3.0, 1e-12);
    EXPECT_NEAR(ahead->uv.x, 0.25, 1e-12);
}

TEST(IntersectTriangle, RangeLimitsAreOpen) {
    // t = 3 for this ray.
    EXPECT_FALSE(intersect_triangle(ray_up_to(1.5, 2.5), kTriangle, {0.0, 3.0})) << "t = 3 equals max";
    EXPECT_FALSE(intersect_triangle(ray_up_to(1.5, 2.5), kTriangle, {3.0, 5.0})) << "t = 3 equals min";
    EXPECT_TRUE(intersect_triangle(ray_up_to(1.5, 2.5), kTriangle, {2.9, 3.1}));
}
