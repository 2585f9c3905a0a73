// Ray intersections with the framework's own shapes (boxes, open cones and
// cylinders), and bounding boxes of every shape.
#include "test_helpers.hpp"
#include "whitted/primitive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

const Box kBox{{-1, -2, -3}, {1, 2, 3}};
const Cone kCylinder{{0, 0, 0}, 1.0, {0, 2, 0}, 1.0};  // radius 1 around the y axis, 0 <= y <= 2
const Cone kPointed{{0, 0, 0}, 2.0, {0, 2, 0}, 0.0};   // radius 2 - y: a 45-degree cone with its tip at y = 2

/// A point on the cone's surface at height fraction u in [0, 1] and angle phi.
Point3 cone_point(const Cone& cone, double u, double phi) {
    const Vec3 a = glm::normalize(cone.apex - cone.base);
    const Vec3 across = glm::normalize(glm::cross(a, std::abs(a.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 other = glm::cross(a, across);
    const double r = cone.base_radius + u * (cone.apex_radius - cone.base_radius);
    return cone.base + u * (cone.apex - cone.base) + r * (std::cos(phi) * across + std::sin(phi) * other);
}

/// True when the box holds p, allowing for rounding.
bool contains(const Aabb& box, const Point3& p) {
    const double e = 1e-12 * (1.0 + max_abs_component(p));
    return glm::all(glm::lessThanEqual(box.min - e, p)) && glm::all(glm::lessThanEqual(p, box.max + e));
}

} // namespace

TEST(Box, RayFromOutsideEntersThroughTheNearFace) {
    // From x = -5 along +x: the face x = -1 at t = 4, outward normal (-1, 0, 0).
    const auto hit = intersect_box(make_ray({-5, 0.5, 1}, {1, 0, 0}), kBox, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {-1, 0.5, 1}));
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}));
    EXPECT_TRUE(hit->front_face);
}

TEST(Box, RayAlongANegativeAxisEntersThroughTheMaxFace) {
    const auto hit = intersect_box(make_ray({0, 0, 10}, {0, 0, -1}), kBox, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 7.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0, 1}));
    EXPECT_TRUE(hit->front_face);
}

TEST(Box, RayFromInsideLeavesThroughTheFarFace) {
    // From the centre along +y: the face y = 2 at t = 2; outward (0, 1, 0) turned to face the ray.
    const auto hit = intersect_box(make_ray({0, 0, 0}, {0, 1, 0}), kBox, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, -1, 0}));
    EXPECT_FALSE(hit->front_face);
}

TEST(Box, MissesBesideBehindAndOutsideTheRange) {
    EXPECT_FALSE(intersect_box(make_ray({-5, 2.5, 0}, {1, 0, 0}), kBox, {}));
    EXPECT_FALSE(intersect_box(make_ray({5, 0, 0}, {1, 0, 0}), kBox, {}));
    EXPECT_FALSE(intersect_box(make_ray({-5, 0, 0}, {1, 0, 0}), kBox, {0.0, 4.0}));
    EXPECT_FALSE(intersect_box(make_ray({-5, 0, 0}, {1, 0, 0}), kBox, {6.0, kInfinity}));
}

TEST(Box, RangeStartingInsideGivesTheExitFace) {
    // Entry t = 4 is excluded by t > 4.5; the exit x = 1 at t = 6 is seen from inside.
    const auto hit = intersect_box(make_ray({-5, 0, 0}, {1, 0, 0}), kBox, {4.5, kInfinity});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}));
    EXPECT_FALSE(hit->front_face);
}

TEST(Box, DiagonalRayHitsTheCornerAtTheRightDistance) {
    // From (2, 3, 4) towards the corner (1, 2, 3): distance sqrt(3).
    const auto hit = intersect_box(make_ray({2, 3, 4}, {-1, -1, -1}), kBox, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(3.0), 1e-12);
    EXPECT_TRUE(near(hit->point, {1, 2, 3}, 1e-12));
    EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-15);
}

TEST(Box, RaySlidingAlongAFaceCountsAsAMiss) {
    // In the plane y = 2 of the top face: 0 * infinity gives NaN for that slab, which must not become a hit.
    EXPECT_FALSE(intersect_box(make_ray({-5, 2, 0}, {1, 0, 0}), kBox, {}));
}

TEST(Cone, CylinderIsHitFromTheSideWithAnOutwardNormal) {
    // From x = -5 at height 1 along +x: the wall x = -1 at t = 4, normal (-1, 0, 0).
    const auto hit = intersect_cone(make_ray({-5, 1, 0}, {1, 0, 0}), kCylinder, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {-1, 1, 0}, 1e-12));
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}, 1e-12));
    EXPECT_TRUE(hit->front_face);
}

TEST(Cone, RayFromTheAxisHitsTheWallFromInside) {
    const auto hit = intersect_cone(make_ray({0, 1, 0}, {1, 0, 0}), kCylinder, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}, 1e-12));
    EXPECT_FALSE(hit->front_face);
}

TEST(Cone, CylinderHasNoCapsSoRaysAlongTheAxisPassThrough) {
    // Parallel to the axis: A = B = 0 in the quadratic; the answer must be "no hit", not NaN.
    EXPECT_FALSE(intersect_cone(make_ray({0, -5, 0}, {0, 1, 0}), kCylinder, {}));
    EXPECT_FALSE(intersect_cone(make_ray({0.5, -5, 0.5}, {0, 1, 0}), kCylinder, {}));
    EXPECT_FALSE(intersect_cone(make_ray({1, -5, 0}, {0, 1, 0}), kCylinder, {}));
}

TEST(Cone, TangentRayTouchesTheCylinderOnce) {
    // The line y = 1, z = 1 grazes the wall at (0, 1, 1): B = 0 and C = 1 - 1 = 0, a double root t = 5.
    const auto hit = intersect_cone(make_ray({-5, 1, 1}, {1, 0, 0}), kCylinder, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {0, 1, 1}, 1e-12));
    EXPECT_FALSE(intersect_cone(make_ray({-5, 1, 1.000001}, {1, 0, 0}), kCylinder, {}));
}

TEST(Cone, HitsBeyondTheEndsOfTheAxisAreRejected) {
    EXPECT_FALSE(intersect_cone(make_ray({-5, 2.5, 0}, {1, 0, 0}), kCylinder, {}));
    EXPECT_FALSE(intersect_cone(make_ray({-5, -0.1, 0}, {1, 0, 0}), kCylinder, {}));
}

TEST(Cone, RayEnteringThroughTheOpenEndHitsTheInnerWall) {
    // From (0, 2.5, 0) down at 45 degrees: x = 1 is reached at y = 1.5, after sqrt(2).
    const auto hit = intersect_cone(make_ray({0, 2.5, 0}, {1, -1, 0}), kCylinder, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(near(hit->point, {1, 1.5, 0}, 1e-12));
    EXPECT_FALSE(hit->front_face);
}

TEST(Cone, RangeSkipsTheNearWallAndFindsTheFarOne) {
    // Roots t = 4 and t = 6; t > 4 excludes the first.
    const auto hit = intersect_cone(make_ray({-5, 1, 0}, {1, 0, 0}), kCylinder, {4.0, kInfinity});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.0, 1e-12);
    EXPECT_FALSE(hit->front_face);
    EXPECT_FALSE(intersect_cone(make_ray({-5, 1, 0}, {1, 0, 0}), kCylinder, {0.0, 3.9}));
    EXPECT_FALSE(intersect_cone(make_ray({5, 1, 0}, {1, 0, 0}), kCylinder, {}));
}

TEST(Cone, PointedConeNormalTiltsTowardsTheTip) {
    // At height 1 the radius is 2 - 1 = 1: hit at (-1, 1, 0), t = 4. The surface |p_perp| = 2 - y has
    // gradient (p_perp / |p_perp|) + a = (-1, 1, 0), so the outward normal is (-1, 1, 0) / sqrt(2).
    const auto hit = intersect_cone(make_ray({-5, 1, 0}, {1, 0, 0}), kPointed, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, glm::normalize(Vec3(-1, 1, 0)), 1e-12));
    EXPECT_TRUE(hit->front_face);
}

TEST(Cone, RayParallelToASlantLineHasOneRoot) {
    // Ray y = x in the plane z = 0, parallel to the slant line |x| = 1 - y of this cone: the quadratic's
    // A vanishes, and the one root is where x = 1 - x, i.e. (0.5, 0.5, 0), 1.5 sqrt(2) from (-1, -1, 0).
    const Cone cone{{0, 0, 0}, 1.0, {0, 1, 0}, 0.0};
    const auto hit = intersect_cone(make_ray({-1, -1, 0}, {1, 1, 0}), cone, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.5 * std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(near(hit->point, {0.5, 0.5, 0}, 1e-12));
    EXPECT_FALSE(hit->front_face); // the ray crossed the open base and meets the wall from inside
}

TEST(Cone, RayThroughThePointedTipGivesAFiniteUnitNormal) {
    // The gradient vanishes at the tip (0, 2, 0); the hit must still carry a usable normal.
    const auto hit = intersect_cone(make_ray({-5, 2, 0}, {1, 0, 0}), kPointed, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-12);
    EXPECT_TRUE(is_finite(hit->normal));
    EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-12);
}

TEST(Cone, InwardConeFlipsTheSide) {
    Cone inward = kCylinder;
    inward.inward = true;
    const auto hit = intersect_cone(make_ray({-5, 1, 0}, {1, 0, 0}), inward, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_FALSE(hit->front_face);
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}, 1e-12)); // still facing the ray
}

TEST(Cone, TiltedTruncatedConeHitsLieOnItsSurface) {
    // Rays aimed at known surface points must come back with a point at distance r(s) from the axis.
    const Cone cone{{1, 2, 3}, 0.5, {3, 5, 4}, 1.5};
    const Vec3 a = glm::normalize(cone.apex - cone.base);
    const double length = glm::length(cone.apex - cone.base);
    for (double u : {0.1, 0.5, 0.9}) {
        for (double phi : {0.3, 2.0, 4.5}) {
            const Point3 target = cone_point(cone, u, phi);
            const Vec3 radial = target - (cone.base + u * (cone.apex - cone.base));
            // Come in from outside along the radial direction, slightly tilted.
            const Ray ray = make_ray(target + 10.0 * radial + Vec3(0.01, 0, 0), -radial);
            const auto hit = intersect_cone(ray, cone, {});
            ASSERT_TRUE(hit) << "u " << u << " phi " << phi;
            const Vec3 offset = hit->point - cone.base;
            const double s = glm::dot(offset, a);
            const double r = cone.base_radius + s / length * (cone.apex_radius - cone.base_radius);
            EXPECT_NEAR(glm::length(offset - s * a), r, 1e-9);
            EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-12);
            EXPECT_TRUE(hit->front_face);
        }
    }
}

TEST(Cone, FarAwayOriginStillLandsOnTheWall) {
    // From ten million units away along a skew direction: the hit point must still be at distance 1
    // from the axis. Without care, B^2 - AC cancels about 14 of the 16 digits of the discriminant.
    const Point3 target(std::cos(0.7), 1.3, std::sin(0.7));
    const Vec3 direction = glm::normalize(Vec3(0.8, -0.01, 0.6));
    const Ray ray{target - 1e7 * direction, direction};
    const auto hit = intersect_cone(ray, kCylinder, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(std::hypot(hit->point.x, hit->point.z), 1.0, 1e-8);
}

TEST(Bounds, EveryBoundedShapeContainsItsSurfacePoints) {
    const Sphere sphere{{1, -2, 3}, 1.5};
    const Triangle triangle{{1, 1, 1}, {-3, 2, 0.5}, {0, -4, 2}};
    const Cone cone{{1, 2, 3}, 0.5, {3, 5, 4}, 1.5};
    const auto sphere_box = bounds(sphere), triangle_box = bounds(triangle), box_box = bounds(kBox),
               cone_box = bounds(cone);
    ASSERT_TRUE(sphere_box && triangle_box && box_box && cone_box);
    for (int i = 0; i <= 16; ++i) {
        const double u = i / 16.0, phi = 2.0 * kPi * u * 5.0, theta = kPi * u;
        const Vec3 on_sphere(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        EXPECT_TRUE(contains(*sphere_box, sphere.center + sphere.radius * on_sphere));
        EXPECT_TRUE(contains(*triangle_box, triangle.p0 + u * (triangle.p1 - triangle.p0) +
                                                (1.0 - u) * 0.5 * (triangle.p2 - triangle.p0)));
        EXPECT_TRUE(contains(*box_box, glm::mix(kBox.min, kBox.max, Vec3(u, 1.0 - u, 0.5))));
        EXPECT_TRUE(contains(*cone_box, cone_point(cone, u, phi)));
    }
    // The extreme points are on the boxes' faces, so the boxes are tight there.
    EXPECT_TRUE(near(sphere_box->max, sphere.center + Vec3(1.5)));
    EXPECT_FALSE(bounds(Plane{{0, 0, 0}, {0, 1, 0}}));
}
