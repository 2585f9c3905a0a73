// Ray intersections with the shapes of lab 1 (the solution's sphere, plane and
// triangle), the dispatcher `intersect()` and `closest_hit()` over a span.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"
#include "whitted/primitive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

const Sphere kSphere{{1, 2, 3}, 2.0};
// Outward normal normalize((2, 0, 0) x (0, 0, 3)) = normalize(0, -6, 0) = (0, -1, 0).
const Triangle kTriangle{{1, 1, 1}, {3, 1, 1}, {1, 1, 4}};

} // namespace

TEST(Sphere, RayFromOutsideHitsTheNearSide) {
    // From (1, 2, -7) along +z the ray meets z = 3 - 2 = 1 at t = 8; the normal there is (0, 0, -1).
    const auto hit = intersect_sphere(make_ray({1, 2, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 8.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {1, 2, 1}));
    EXPECT_TRUE(near(hit->normal, {0, 0, -1}));
    EXPECT_TRUE(hit->front_face);
}

TEST(Sphere, RayPassingBesideMisses) {
    // The line x = 1, y = 4.5 passes 2.5 > 2 from the centre.
    EXPECT_FALSE(intersect_sphere(make_ray({1, 4.5, -7}, {0, 0, 1}), kSphere, {}));
}

TEST(Sphere, RayFromTheCentreHitsTheFarSideFromInside) {
    // From the centre along +x: t = r = 2, outward normal (1, 0, 0) turned to face the ray.
    const auto hit = intersect_sphere(make_ray({1, 2, 3}, {1, 0, 0}), kSphere, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {3, 2, 3}));
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}));
    EXPECT_FALSE(hit->front_face);
}

TEST(Sphere, TangentRayTouchesAtOnePoint) {
    // The line x = 1, y = 4 is exactly r = 2 from the centre: one root t = 10 at (1, 4, 3).
    const auto hit = intersect_sphere(make_ray({1, 4, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 10.0, 1e-9);
    EXPECT_TRUE(near(hit->point, {1, 4, 3}, 1e-9));
}

TEST(Sphere, SphereBehindTheOriginIsNotHit) {
    EXPECT_FALSE(intersect_sphere(make_ray({1, 2, 7}, {0, 0, 1}), kSphere, {}));
}

TEST(Sphere, RangeLimitsAreRespectedAndOpen) {
    // Roots t = 8 and t = 12 for this ray.
    const Ray ray = make_ray({1, 2, -7}, {0, 0, 1});
    EXPECT_FALSE(intersect_sphere(ray, kSphere, {0.0, 8.0}));  // 8 itself is outside the open range
    EXPECT_FALSE(intersect_sphere(ray, kSphere, {12.0, 20.0}));
    const auto far = intersect_sphere(ray, kSphere, {8.5, kInfinity});
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->t, 12.0, 1e-12);
    EXPECT_FALSE(far->front_face);
}

TEST(Sphere, InwardSphereSeesTheRayArrivingFromItsOutwardSide) {
    // The outward side of an inward sphere faces the centre: a ray from outside arrives on its back.
    const Sphere inward{kSphere.center, kSphere.radius, true};
    const auto hit = intersect_sphere(make_ray({1, 2, -7}, {0, 0, 1}), inward, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 8.0, 1e-12);
    EXPECT_FALSE(hit->front_face);
    EXPECT_TRUE(near(hit->normal, {0, 0, -1})); // still facing the ray
}

TEST(Plane, RayFromAboveHitsTheFront) {
    // Plane y = 1 with normal +y; from (2, 5, 3) straight down: t = 4 at (2, 1, 3).
    const Plane plane{{0, 1, 0}, {0, 1, 0}};
    const auto hit = intersect_plane(make_ray({2, 5, 3}, {0, -1, 0}), plane, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {2, 1, 3}));
    EXPECT_TRUE(near(hit->normal, {0, 1, 0}));
    EXPECT_TRUE(hit->front_face);
}

TEST(Plane, RayFromBelowHitsTheBack) {
    const Plane plane{{0, 1, 0}, {0, 1, 0}};
    const auto hit = intersect_plane(make_ray({0, -3, 0}, {0, 1, 0}), plane, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, -1, 0}));
    EXPECT_FALSE(hit->front_face);
}

TEST(Plane, ObliqueRayTravelsTheSlantDistance) {
    // From height 2 above y = 1 at 45 degrees: t = 2 sqrt(2), landing 2 further along x.
    const Plane plane{{0, 1, 0}, {0, 1, 0}};
    const auto hit = intersect_plane(make_ray({0, 3, 0}, {1, -1, 0}), plane, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0 * std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(near(hit->point, {2, 1, 0}, 1e-12));
}

TEST(Plane, ParallelRayAndPlaneBehindAreMissed) {
    const Plane plane{{0, 1, 0}, {0, 1, 0}};
    EXPECT_FALSE(intersect_plane(make_ray({0, 3, 0}, {1, 0, 0}), plane, {}));
    EXPECT_FALSE(intersect_plane(make_ray({0, 5, 0}, {0, 1, 0}), plane, {}));
    EXPECT_FALSE(intersect_plane(make_ray({2, 5, 3}, {0, -1, 0}), plane, {0.0, 3.9}));
}

TEST(Triangle, HitReportsBarycentricsOfP1AndP2) {
    // p = p0 + b1 (p1 - p0) + b2 (p2 - p0) with b1 = 0.25, b2 = 0.5: (1.5, 1, 2.5); from y = -2, t = 3.
    const auto hit = intersect_triangle(make_ray({1.5, -2, 2.5}, {0, 1, 0}), kTriangle, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {1.5, 1, 2.5}));
    EXPECT_NEAR(hit->uv.x, 0.25, 1e-12);
    EXPECT_NEAR(hit->uv.y, 0.5, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, -1, 0}));
    EXPECT_TRUE(hit->front_face);
}

TEST(Triangle, RayFromTheBackSeesTheBackFace) {
    const auto hit = intersect_triangle(make_ray({1.5, 4, 2.5}, {0, -1, 0}), kTriangle, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 1, 0}));
    EXPECT_FALSE(hit->front_face);
}

TEST(Triangle, PointOutsideTheHypotenuseIsMissed) {
    // (2.9, 1, 3.9): b1 = 0.95, b2 = 0.9667, b1 + b2 > 1.
    EXPECT_FALSE(intersect_triangle(make_ray({2.9, -2, 3.9}, {0, 1, 0}), kTriangle, {}));
    // (0.9, 1, 2): b1 = -0.05.
    EXPECT_FALSE(intersect_triangle(make_ray({0.9, -2, 2}, {0, 1, 0}), kTriangle, {}));
}

TEST(Triangle, EdgeAndVertexPointsCountAsHits) {
    // Midpoint of p0p1: b1 = 0.5, b2 = 0 exactly (all arithmetic here is exact).
    const auto edge = intersect_triangle(make_ray({2, -2, 1}, {0, 1, 0}), kTriangle, {});
    ASSERT_TRUE(edge);
    EXPECT_EQ(edge->uv, Vec2(0.5, 0.0));
    // The vertex p2: b1 = 0, b2 = 1, b1 + b2 = 1.
    const auto vertex = intersect_triangle(make_ray({1, -2, 4}, {0, 1, 0}), kTriangle, {});
    ASSERT_TRUE(vertex);
    EXPECT_EQ(vertex->uv, Vec2(0.0, 1.0));
}

TEST(Triangle, ParallelRayBehindRayAndShortRangeMiss) {
    EXPECT_FALSE(intersect_triangle(make_ray({1.5, 1, -5}, {0, 0, 1}), kTriangle, {}));
    EXPECT_FALSE(intersect_triangle(make_ray({1.5, 4, 2.5}, {0, 1, 0}), kTriangle, {}));
    EXPECT_FALSE(intersect_triangle(make_ray({1.5, -2, 2.5}, {0, 1, 0}), kTriangle, {0.0, 3.0}));
}

TEST(Intersect, DispatchesEveryShapeAndFillsMaterialAndPrimitive) {
    // Every shape is placed so that the ray from (0, 0, -10) along +z first meets it at z = -1 (t = 9).
    const Ray ray = make_ray({0, 0, -10}, {0, 0, 1});
    const std::vector<Shape> shapes = {
        Sphere{{0, 0, 0}, 1.0},
        Plane{{0, 0, -1}, {0, 0, -1}},
        Triangle{{-1, -1, -1}, {-1, 1, -1}, {1, 0, -1}},
        Box{{-1, -1, -1}, {1, 1, 1}},
        Cone{{0, -1, 0}, 1.0, {0, 1, 0}, 1.0}, // cylinder along y, met from the side
    };
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Primitive primitive{shapes[i], static_cast<std::uint32_t>(7 + i), -1, static_cast<std::uint32_t>(i)};
        const auto hit = intersect(ray, primitive, {});
        ASSERT_TRUE(hit) << "shape " << i;
        EXPECT_NEAR(hit->t, 9.0, 1e-12) << "shape " << i;
        EXPECT_TRUE(near(hit->point, {0, 0, -1}, 1e-12)) << "shape " << i;
        EXPECT_EQ(hit->material, 7 + i);
        EXPECT_EQ(hit->primitive, i);
    }
}

TEST(ClosestHit, PicksTheNearestWhateverTheOrder) {
    // Unit spheres on the x axis at 10, 4 and 7; from the origin along +x their near sides are t = 9, 3, 6.
    const std::vector<Primitive> primitives = {
        {Sphere{{10, 0, 0}, 1.0}, 0, -1, 0},
        {Sphere{{4, 0, 0}, 1.0}, 0, -1, 1},
        {Sphere{{7, 0, 0}, 1.0}, 0, -1, 2},
    };
    const Ray ray = make_ray({0, 0, 0}, {1, 0, 0});
    const auto nearest = closest_hit(ray, primitives, {});
    ASSERT_TRUE(nearest);
    EXPECT_EQ(nearest->primitive, 1u);
    EXPECT_NEAR(nearest->t, 3.0, 1e-12);
    // Starting past the middle sphere: its far side t = 5 is nearer than the third sphere's t = 6.
    const auto beyond = closest_hit(ray, primitives, {3.5, kInfinity});
    ASSERT_TRUE(beyond);
    EXPECT_EQ(beyond->primitive, 1u);
    EXPECT_NEAR(beyond->t, 5.0, 1e-12);
    EXPECT_FALSE(closest_hit(make_ray({0, 0, 0}, {-1, 0, 0}), primitives, {}));
}
