// intersect_plane: t = n . (p - o) / (n . d), kept only inside the open range t_range.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

// The plane y = 1 with its outward normal +y.
const Plane kFloor{{0, 1, 0}, {0, 1, 0}};

} // namespace

TEST(IntersectPlane, RayFromAboveHitsTheFront) {
    // From (2, 5, 3) straight down: n . (p - o) = -4, n . d = -1, t = 4 at (2, 1, 3).
    const auto hit = intersect_plane(make_ray({2, 5, 3}, {0, -1, 0}), kFloor, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {2, 1, 3}));
    EXPECT_TRUE(near(hit->normal, {0, 1, 0}));
    EXPECT_TRUE(hit->front_face) << "the ray comes from the side the normal points to";
}

TEST(IntersectPlane, RayFromBelowHitsTheBackWithTheNormalTurnedDown) {
    const auto hit = intersect_plane(make_ray({0, -3, 0}, {0, 1, 0}), kFloor, {});
    ASSERT_TRUE(hit) << "planes are two-sided: they are hit from behind too";
    EXPECT_NEAR(hit->t, 4.0, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, -1, 0})) << "the normal must be turned to face the ray (use make_hit)";
    EXPECT_FALSE(hit->front_face);
}

TEST(IntersectPlane, ObliqueRayTravelsTheSlantDistance) {
    // From height 2 above y = 1 at 45 degrees: t = 2 sqrt(2), landing 2 further along x.
    const auto hit = intersect_plane(make_ray({0, 3, 0}, {1, -1, 0}), kFloor, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0 * std::sqrt(2.0), 1e-12) << "t is a distance along the unit direction";
    EXPECT_TRUE(near(hit->point, {2, 1, 0}, 1e-12));
}

TEST(IntersectPlane, TiltedPlaneIsMetAtItsOwnDistance) {
    // Plane through (3, 0, 0) with n = (1, 2, 2) / 3. From the origin along +x:
    // n . (p - o) = 1, n . d = 1/3, t = 3. The origin lies on the back side (n . (o - p) = -1).
    const Plane tilted{{3, 0, 0}, Vec3(1, 2, 2) / 3.0};
    const auto hit = intersect_plane(make_ray({0, 0, 0}, {1, 0, 0}), tilted, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0, 1e-12);
    EXPECT_TRUE(near(hit->point, {3, 0, 0}, 1e-12));
    EXPECT_TRUE(near(hit->normal, -Vec3(1, 2, 2) / 3.0, 1e-15));
    EXPECT_FALSE(hit->front_face);
}

TEST(IntersectPlane, GrazingRayHitsFarAway) {
    // From (0, 2, 0) along normalize(1, -0.001, 0): it drops 1 after 1000 along x,
    // so t = 1000 sqrt(1 + 1e-6) at (1000, 1, 0).
    const auto hit = intersect_plane(make_ray({0, 2, 0}, {1, -0.001, 0}), kFloor, {});
    ASSERT_TRUE(hit) << "an almost parallel ray still meets the plane";
    EXPECT_NEAR(hit->t, 1000.0 * std::sqrt(1.0 + 1e-6), 1e-9);
    EXPECT_TRUE(near(hit->point, {1000, 1, 0}, 1e-9));
}

TEST(IntersectPlane, AlmostParallelRayMeetsThePlaneTenMillionAway) {
    // From (0, 2, 0) along normalize(1, -1e-7, 0): n . d = -1e-7 / sqrt(1 + 1e-14), so the ray drops the 1
    // to the plane y = 1 after 1e7 along x: t = 1e7 sqrt(1 + 1e-14), at (1e7, 1, 0). Only n . d == 0 is
    // parallel; a fixed "|n . d| < 1e-6" cuts the horizon off every ground plane.
    const auto hit = intersect_plane(make_ray({0, 2, 0}, {1, -1e-7, 0}), kFloor, {});
    ASSERT_TRUE(hit) << "n . d = -1e-7 is small, not zero: the ray meets the plane";
    EXPECT_NEAR(hit->t, 1e7, 1e-6);
    EXPECT_TRUE(near(hit->point, {1e7, 1, 0}, 1e-6));
    EXPECT_TRUE(hit->front_face);
}

TEST(IntersectPlane, ParallelRayIsMissed) {
    EXPECT_FALSE(intersect_plane(make_ray({0, 3, 0}, {1, 0, 0}), kFloor, {})) << "n . d = 0: no intersection";
    // From the same point turned 45 degrees down, (1, -1, 0) / sqrt 2: it falls 2 to y = 1 at x = 2, t = 2 sqrt 2.
    const auto down = intersect_plane(make_ray({0, 3, 0}, {1, -1, 0}), kFloor, {});
    ASSERT_TRUE(down) << "turned down, the ray meets the plane";
    EXPECT_NEAR(down->t, 2.0 * std::sqrt(2.0), 1e-12);
}

TEST(IntersectPlane, PlaneBehindTheOriginIsMissed) {
    // From (0, 5, 0) going up, the plane y = 1 is at t = -4.
    EXPECT_FALSE(intersect_plane(make_ray({0, 5, 0}, {0, 1, 0}), kFloor, {}))
        << "t = -4 is behind the origin: outside t_range (0, infinity)";
    EXPECT_FALSE(intersect_plane(make_ray({3, 1.5, 0}, {1, 0.2, 0}), kFloor, {}));
    // Turned around (going down), the first ray has the plane ahead: t = 4, seen from above.
    const auto ahead = intersect_plane(make_ray({0, 5, 0}, {0, -1, 0}), kFloor, {});
    ASSERT_TRUE(ahead) << "from (0, 5, 0) going down the plane y = 1 is ahead";
    EXPECT_NEAR(ahead->t, 4.0, 1e-12);
    EXPECT_TRUE(ahead->front_face);
}

TEST(IntersectPlane, RangeLimitsAreOpen) {
    // t = 4 for this ray.
    const Ray ray = make_ray({2, 5, 3}, {0, -1, 0});
    EXPECT_FALSE(intersect_plane(ray, kFloor, {0.0, 3.9}));
    EXPECT_FALSE(intersect_plane(ray, kFloor, {0.0, 4.0})) << "t = 4 equals max: outside the open range";
    EXPECT_FALSE(intersect_plane(ray, kFloor, {4.0, 9.0})) << "t = 4 equals min: outside the open range";
    EXPECT_TRUE(intersect_plane(ray, kFloor, {3.9, 4.1}));
}
