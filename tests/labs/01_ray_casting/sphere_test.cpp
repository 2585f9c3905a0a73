// intersect_sphere: the nearest root of |o + t d - c|^2 = r^2 inside the open range t_range,
// with the unit normal turned to face the ray (make_hit) and front_face set.
#include "test_helpers.hpp"
#include "whitted/labs.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace whitted;
using whitted::testing_helpers::make_ray;
using whitted::testing_helpers::near;

namespace {

// Radius 2, so that a normal p - c not divided by the radius has length 2.
const Sphere kSphere{{1, 2, 3}, 2.0};

} // namespace

TEST(IntersectSphere, RayFromOutsideHitsTheNearSide) {
    // From (1, 2, -7) along +z the ray meets z = 3 - 2 = 1 at t = 8 (and leaves at t = 12);
    // the outward normal there is (p - c) / r = (0, 0, -2) / 2 = (0, 0, -1).
    const auto hit = intersect_sphere(make_ray({1, 2, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit) << "the ray goes straight through the centre";
    EXPECT_NEAR(hit->t, 8.0, 1e-12) << "the nearer of the two roots 8 and 12";
    EXPECT_TRUE(near(hit->point, {1, 2, 1}));
    EXPECT_TRUE(near(hit->normal, {0, 0, -1})) << "the normal is (p - c) / r: unit length, pointing out";
    EXPECT_TRUE(hit->front_face);
}

TEST(IntersectSphere, ObliqueHitHasAUnitNormalFacingTheRay) {
    // From (1, 2 + 1.2, -7) along +z: the line is 1.2 from the centre, the half chord is
    // sqrt(4 - 1.44) = 1.6, so t = 10 - 1.6 = 8.4 at (1, 3.2, 1.4); normal (0, 1.2, -1.6) / 2 = (0, 0.6, -0.8).
    const auto hit = intersect_sphere(make_ray({1, 3.2, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 8.4, 1e-12);
    EXPECT_TRUE(near(hit->normal, {0, 0.6, -0.8}, 1e-12)) << "divide p - c by the radius to get a unit normal";
    EXPECT_LE(glm::dot(hit->normal, Vec3(0, 0, 1)), 0.0) << "the normal must face the incoming ray";
}

TEST(IntersectSphere, RayPassingBesideMisses) {
    // The line x = 1, y = 4.5 passes 2.5 > 2 from the centre: the discriminant is negative.
    EXPECT_FALSE(intersect_sphere(make_ray({1, 4.5, -7}, {0, 0, 1}), kSphere, {}));
    // Diagonal line from (1, 2 - 10, 3 + 10) towards +y only: passes 10 from the centre.
    EXPECT_FALSE(intersect_sphere(make_ray({1, -8, 13}, {0, 1, 0}), kSphere, {}));
    // Moved in to y = 3.6, the line passes 1.6 from the centre: half chord sqrt(4 - 2.56) = 1.2, t = 10 - 1.2.
    const auto inside = intersect_sphere(make_ray({1, 3.6, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(inside) << "1.6 from the centre, inside the radius 2: a hit";
    EXPECT_NEAR(inside->t, 8.8, 1e-12);
}

TEST(IntersectSphere, RayFromTheCentreHitsTheFarSideFromInside) {
    // From the centre along +x the roots are t = -2 (behind the origin) and t = 2: only t = 2 counts.
    // The outward normal (1, 0, 0) is turned to face the ray: (-1, 0, 0), and front_face is false.
    const auto hit = intersect_sphere(make_ray({1, 2, 3}, {1, 0, 0}), kSphere, {});
    ASSERT_TRUE(hit) << "a ray starting inside the sphere must find the far wall";
    EXPECT_NEAR(hit->t, 2.0, 1e-12) << "the root t = -2 is behind the ray's origin: take the other one";
    EXPECT_TRUE(near(hit->point, {3, 2, 3}));
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0})) << "the normal must be turned to face the ray (use make_hit)";
    EXPECT_FALSE(hit->front_face) << "the ray arrives from the inside";
}

TEST(IntersectSphere, TangentRayTouchesAtOnePoint) {
    // The line x = 1, y = 4 is exactly r = 2 from the centre: a double root t = 10 at (1, 4, 3).
    const auto hit = intersect_sphere(make_ray({1, 4, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit) << "a zero discriminant is still a hit";
    EXPECT_NEAR(hit->t, 10.0, 1e-9);
    EXPECT_TRUE(near(hit->point, {1, 4, 3}, 1e-9));
}

TEST(IntersectSphere, GrazingRayJustInsideHitsNearTheTangentPoint) {
    // The line y = 3.99 is 1.99 from the centre: half chord sqrt(4 - 1.99^2) = sqrt(0.0399),
    // so t = 10 - sqrt(0.0399) and the normal is (0, 1.99, -sqrt(0.0399)) / 2.
    const double half_chord = std::sqrt(0.0399);
    const auto hit = intersect_sphere(make_ray({1, 3.99, -7}, {0, 0, 1}), kSphere, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 10.0 - half_chord, 1e-12);
    EXPECT_TRUE(near(hit->normal, Vec3(0, 1.99, -half_chord) / 2.0, 1e-12));
    EXPECT_TRUE(hit->front_face);
}

TEST(IntersectSphere, SpheresTenMillionAwayKeepTheirDigits) {
    // A sphere of radius r at (1e7, 0, 0), seen from the origin side along +x by a line 0.6 r off its
    // centre: the half chord is sqrt(r^2 - 0.36 r^2) = 0.8 r, so t = 1e7 - 0.8 r at (1e7 - 0.8 r, 0.6 r, 0)
    // with the normal (-0.8, 0.6, 0). Here b^2 and c' are both about 1e14, whose doubles are 1/64 apart:
    // b^2 - c' loses the 0.64 r^2 it should give (a radius-1 sphere's t is off by about 4e-4, a
    // radius-1e-3 one is missed or hit at its centre line); r^2 - |oc - b d|^2 keeps it.
    for (const double r : {1.0, 1e-3}) {
        SCOPED_TRACE(::testing::Message() << "radius " << r);
        const Sphere far{{1e7, 0, 0}, r};
        const auto hit = intersect_sphere(make_ray({0, 0.6 * r, 0}, {1, 0, 0}), far, {});
        ASSERT_TRUE(hit) << "the line passes 0.6 r from the centre";
        EXPECT_NEAR(hit->t, 1e7 - 0.8 * r, 1e-6) << "compute the discriminant as r^2 - |oc - b d|^2 (see the handout)";
        // The hit point's x is rounded to about 2e-9 (the spacing of doubles near 1e7), which moves the
        // normal (p - c) / r by 2e-6 when r = 1e-3.
        EXPECT_TRUE(near(hit->normal, {-0.8, 0.6, 0}, 1e-5));
        EXPECT_TRUE(hit->front_face);
    }
}

TEST(IntersectSphere, SphereBehindTheOriginIsNotHit) {
    // Both roots (t = -12 and t = -8) are negative: the sphere lies behind the ray.
    EXPECT_FALSE(intersect_sphere(make_ray({1, 2, 7}, {0, 0, 1}), kSphere, {}))
        << "t must lie inside t_range, whose minimum is 0: hits behind the origin do not count";
    // Turned around (along -z) the roots are t = 2 and t = 6: the sphere is ahead, its near side at z = 5.
    const auto ahead = intersect_sphere(make_ray({1, 2, 7}, {0, 0, -1}), kSphere, {});
    ASSERT_TRUE(ahead) << "along -z the sphere is ahead of the origin";
    EXPECT_NEAR(ahead->t, 2.0, 1e-12);
    EXPECT_TRUE(near(ahead->point, {1, 2, 5}));
}

TEST(IntersectSphere, RangeLimitsAreRespectedAndOpen) {
    // Roots t = 8 and t = 12 for this ray; Interval::surrounds is min < t < max (strict).
    const Ray ray = make_ray({1, 2, -7}, {0, 0, 1});
    EXPECT_FALSE(intersect_sphere(ray, kSphere, {0.0, 8.0})) << "t = 8 equals max: outside the open range";
    EXPECT_FALSE(intersect_sphere(ray, kSphere, {12.0, 20.0})) << "t = 12 equals min: outside the open range";
    EXPECT_FALSE(intersect_sphere(ray, kSphere, {8.5, 11.5})) << "both roots lie outside (8.5, 11.5)";
    const auto far = intersect_sphere(ray, kSphere, {8.0, kInfinity});
    ASSERT_TRUE(far) << "with min = 8 the nearer root is excluded but the far one (12) is not";
    EXPECT_NEAR(far->t, 12.0, 1e-12);
    EXPECT_FALSE(far->front_face) << "the far root is met from the inside";
    EXPECT_TRUE(near(far->normal, {0, 0, -1})) << "outward (0, 0, 1) turned to face the ray";
}

TEST(IntersectSphere, InwardSphereSeesTheRayArrivingFromItsOutwardSide) {
    // The outward side of an inward sphere faces the centre: a ray from outside arrives on its back.
    const Sphere inward{kSphere.center, kSphere.radius, true};
    const auto hit = intersect_sphere(make_ray({1, 2, -7}, {0, 0, 1}), inward, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 8.0, 1e-12);
    EXPECT_FALSE(hit->front_face) << "an inward sphere's outward normal is (c - p) / r";
    EXPECT_TRUE(near(hit->normal, {0, 0, -1})) << "the normal still faces the ray";
}

TEST(IntersectSphere, InwardSphereSeenFromInsideShowsItsFrontFace) {
    // From the centre along +x: t = 2 at (3, 2, 3); outward normal of the inward sphere (c - p) / r = (-1, 0, 0)
    // already faces the ray, so front_face is true.
    const Sphere inward{kSphere.center, kSphere.radius, true};
    const auto hit = intersect_sphere(make_ray({1, 2, 3}, {1, 0, 0}), inward, {});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0, 1e-12);
    EXPECT_TRUE(hit->front_face) << "inward spheres are meant to be seen from inside";
    EXPECT_TRUE(near(hit->normal, {-1, 0, 0}));
}
