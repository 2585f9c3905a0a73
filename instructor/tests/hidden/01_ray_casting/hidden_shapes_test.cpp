// Hidden lab 1 tests of the shapes and closest_hit: far-away and tiny shapes, huge spheres,
// tilted planes, slivers and obtuse triangles, nested spheres and long primitive lists.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"
#include "whitted/primitive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

TEST(HiddenIntersectSphere, FarAwaySphereIsHitOnItsNearSide) {
    // Centre (1e4, 1e4, 0), r 5, from the origin along (1, 1, 0) / sqrt 2: t = 1e4 sqrt 2 - 5.
    const auto hit = intersect_sphere(make_ray({0, 0, 0}, {1, 1, 0}), Sphere{{1e4, 1e4, 0}, 5.0}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1e4 * std::sqrt(2.0) - 5.0, 1e-8);
    EXPECT_TRUE(near(hit->normal, -glm::normalize(Vec3(1, 1, 0)), 1e-9));
    EXPECT_TRUE(hit->front_face);
}

TEST(HiddenIntersectSphere, TinySphereIsHitOffCentre) {
    // r = 1e-3 at (0, 0, -10); a ray along -z 0.5e-3 off the axis: half chord sqrt(1e-6 - 0.25e-6).
    const auto hit = intersect_sphere(make_ray({0.5e-3, 0, 0}, {0, 0, -1}), Sphere{{0, 0, -10}, 1e-3}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 10.0 - std::sqrt(0.75e-6), 1e-12);
    EXPECT_TRUE(near(hit->normal, {0.5, 0, std::sqrt(0.75)}, 1e-9)) << "(p - c) / r with r = 1e-3";
}

TEST(HiddenIntersectSphere, HugeSphereActsAsAFloorSeenFromAboveAndBelow) {
    // Centre (0, -1000, 0), r 1000: its top is the origin.
    const Sphere planet{{0, -1000, 0}, 1000.0};
    const auto above = intersect_sphere(make_ray({0, 5, 0}, {0, -1, 0}), planet, {});
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->t, 5.0, 1e-10);
    EXPECT_TRUE(near(above->normal, {0, 1, 0}, 1e-12));
    EXPECT_FALSE(intersect_sphere(make_ray({0, 5, 0}, {0, 1, 0}), planet, {})) << "going up, away from the sphere";
    const auto below = intersect_sphere(make_ray({0, -5, 0}, {0, 1, 0}), planet, {});
    ASSERT_TRUE(below) << "from inside, the top is ahead at t = 5";
    EXPECT_NEAR(below->t, 5.0, 1e-10);
    EXPECT_TRUE(near(below->normal, {0, -1, 0}, 1e-12));
    EXPECT_FALSE(below->front_face);
}

TEST(HiddenIntersectSphere, InwardSphereSeenThroughToItsFarWall) {
    // Inward sphere at the origin, r 3; the line y = 1 along +x: roots 10 -+ sqrt 8 from (-10, 1, 0).
    const Sphere shell{{0, 0, 0}, 3.0, true};
    const Ray ray = make_ray({-10, 1, 0}, {1, 0, 0});
    const auto near_wall = intersect_sphere(ray, shell, {});
    ASSERT_TRUE(near_wall);
    EXPECT_NEAR(near_wall->t, 10.0 - std::sqrt(8.0), 1e-12);
    EXPECT_FALSE(near_wall->front_face) << "from outside, an inward sphere shows its back";
    EXPECT_TRUE(near(near_wall->normal, Vec3(-std::sqrt(8.0), 1, 0) / 3.0, 1e-12));
    const auto far_wall = intersect_sphere(ray, shell, {8.0, kInfinity});
    ASSERT_TRUE(far_wall);
    EXPECT_NEAR(far_wall->t, 10.0 + std::sqrt(8.0), 1e-12);
    EXPECT_TRUE(far_wall->front_face) << "from inside, an inward sphere shows its front";
    EXPECT_TRUE(near(far_wall->normal, Vec3(-std::sqrt(8.0), -1, 0) / 3.0, 1e-12));
}

TEST(HiddenIntersectPlane, TiltedPlaneFarFromTheOrigin) {
    // Through (500, 500, 500) with n = (1, 1, 1) / sqrt 3; from the origin along n: t = 500 sqrt 3, back side.
    const Vec3 n = glm::normalize(Vec3(1, 1, 1));
    const auto hit = intersect_plane(make_ray({0, 0, 0}, {1, 1, 1}), Plane{{500, 500, 500}, n}, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 500.0 * std::sqrt(3.0), 1e-9);
    EXPECT_TRUE(near(hit->point, {500, 500, 500}, 1e-9));
    EXPECT_TRUE(near(hit->normal, -n, 1e-15));
    EXPECT_FALSE(hit->front_face);
    EXPECT_FALSE(intersect_plane(make_ray({0, 0, 0}, {-1, -2, 0}), Plane{{500, 500, 500}, n}, {}))
        << "going away from the plane: t < 0";
    EXPECT_FALSE(intersect_plane(make_ray({0, 0, 0}, {1, -1, 0}), Plane{{500, 500, 500}, n}, {})) << "parallel";
}

TEST(HiddenIntersectPlane, RangeAroundTheHit) {
    // Plane x = 10 facing -x; from the origin along +x: t = 10.
    const Plane wall{{10, 3, -4}, {-1, 0, 0}};
    const Ray ray = make_ray({0, 0, 0}, {1, 0, 0});
    EXPECT_FALSE(intersect_plane(ray, wall, {10.0, 20.0}));
    EXPECT_FALSE(intersect_plane(ray, wall, {0.0, 10.0}));
    const auto hit = intersect_plane(ray, wall, {9.999, 10.001});
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit->front_face);
}

TEST(HiddenIntersectTriangle, FarAwayTriangleReportsItsBarycentrics) {
    // p0 = (1000, 2000, -3000), p1 = p0 + (10, 0, 0), p2 = p0 + (0, 10, 0), normal +z.
    // From p0 + (2, 3, 50) down -z: t = 50 at p0 + (2, 3, 0): b1 = 0.2, b2 = 0.3.
    const Point3 p0(1000, 2000, -3000);
    const Triangle triangle{p0, p0 + Vec3(10, 0, 0), p0 + Vec3(0, 10, 0)};
    const auto hit = intersect_triangle(make_ray(p0 + Vec3(2, 3, 50), {0, 0, -1}), triangle, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 50.0, 1e-10);
    EXPECT_NEAR(hit->uv.x, 0.2, 1e-12);
    EXPECT_NEAR(hit->uv.y, 0.3, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0, 1}));
    EXPECT_TRUE(hit->front_face);
}

TEST(HiddenIntersectTriangle, SliverTriangleEdgeIsRespected) {
    // (0,0,0), (1,0,0), (0,0.01,0): at x = 0.5 the hypotenuse is at y = 0.005.
    const Triangle sliver{{0, 0, 0}, {1, 0, 0}, {0, 0.01, 0}};
    const auto inside = intersect_triangle(make_ray({0.5, 0.0049, 1}, {0, 0, -1}), sliver, {});
    ASSERT_TRUE(inside) << "b1 = 0.5, b2 = 0.49: inside";
    EXPECT_NEAR(inside->uv.y, 0.49, 1e-12);
    EXPECT_FALSE(intersect_triangle(make_ray({0.5, 0.0051, 1}, {0, 0, -1}), sliver, {})) << "b1 + b2 = 1.01";
    EXPECT_FALSE(intersect_triangle(make_ray({0.5, 0.0099, 1}, {0, 0, -1}), sliver, {})) << "b1 + b2 = 1.49";
}

TEST(HiddenIntersectTriangle, ObtuseTriangleHitObliquelyFromBehind) {
    // (0,0,0), (4,0,0), (1,3,0): normal (0, 0, 12) / 12 = +z. The point 0.5 p0 + 0.25 p1 + 0.25 p2 = (1.25, 0.75, 0)
    // is reached from (-0.75, -0.25, -3) along (2, 1, 3) at t = sqrt 14, from the back (-z side).
    const Triangle obtuse{{0, 0, 0}, {4, 0, 0}, {1, 3, 0}};
    const auto hit = intersect_triangle(make_ray({-0.75, -0.25, -3}, {2, 1, 3}), obtuse, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(14.0), 1e-12);
    EXPECT_NEAR(hit->uv.x, 0.25, 1e-12);
    EXPECT_NEAR(hit->uv.y, 0.25, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0, -1}));
    EXPECT_FALSE(hit->front_face);
    EXPECT_FALSE(intersect_triangle(make_ray({3.5, 2, 1}, {0, 0, -1}), obtuse, {})) << "beyond the edge p1 p2";
}

TEST(HiddenClosestHit, NestedSpheresAreFoundLayerByLayer) {
    // Spheres at the origin with r 1 (id 0) and r 3 (id 1); from (-10, 0, 0) along +x: t = 7, 9, 11, 13.
    const std::vector<Primitive> nested = {{Sphere{{0, 0, 0}, 1.0}, 0, -1, 0}, {Sphere{{0, 0, 0}, 3.0}, 0, -1, 1}};
    const Ray ray = make_ray({-10, 0, 0}, {1, 0, 0});
    const double starts[] = {0.0, 7.5, 9.5, 11.5};
    const double expected_t[] = {7.0, 9.0, 11.0, 13.0};
    const unsigned expected_id[] = {1, 0, 0, 1};
    for (int i = 0; i < 4; ++i) {
        const auto hit = closest_hit(ray, nested, {starts[i], kInfinity});
        ASSERT_TRUE(hit) << "from t = " << starts[i];
        EXPECT_NEAR(hit->t, expected_t[i], 1e-12) << "from t = " << starts[i];
        EXPECT_EQ(hit->primitive, expected_id[i]) << "from t = " << starts[i];
    }
    EXPECT_FALSE(closest_hit(ray, nested, {13.0, kInfinity}));
}

TEST(HiddenClosestHit, TwentyScrambledSpheresGiveTheNearest) {
    // Unit spheres at x = 5 + 3k, listed in the order k = (7 i + 3) mod 20:
    // the nearest (k = 0, listed as i = 11) is at t = 4.
    std::vector<Primitive> spheres;
    for (std::uint32_t i = 0; i < 20; ++i) {
        const double k = (7 * i + 3) % 20;
        spheres.push_back({Sphere{{5 + 3 * k, 0, 0}, 1.0}, 0, -1, i});
    }
    const auto hit = closest_hit(make_ray({0, 0, 0}, {1, 0, 0}), spheres, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_EQ(hit->primitive, 11u);
    EXPECT_FALSE(closest_hit(make_ray({0, 0, 0}, {1, 0, 0}), spheres, {0.0, 3.9}));
}
